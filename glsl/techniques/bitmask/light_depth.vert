#version 450 core
// `bitmask` light depth map: position from the light's centre, and the distance of the point
// along the light's forward axis (the z of the light frame the receivers are measured in).
layout(location = 0) in vec3 a_position;
uniform mat4 u_model;
uniform mat4 u_view_proj;
uniform vec3 u_light_centre;
uniform vec3 u_light_forward;

out float v_z;

void main() {
    vec4 world = u_model * vec4(a_position, 1.0);
    v_z = dot(world.xyz - u_light_centre, u_light_forward);
    gl_Position = u_view_proj * world;
}
