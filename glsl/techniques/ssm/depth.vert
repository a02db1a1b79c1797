#version 450 core
// `ssm` occluder and receiver maps: position from the light's centre, linear depth
// (distance along the light's forward axis - near) / (far - near).
layout(location = 0) in vec3 a_position;
uniform mat4 u_model;
uniform mat4 u_view_proj;
uniform vec3 u_light_centre;
uniform vec3 u_light_forward;
uniform float u_near;
uniform float u_inv_range;  // 1 / (far - near)

out float v_depth;

void main() {
    vec4 world = u_model * vec4(a_position, 1.0);
    v_depth = (dot(world.xyz - u_light_centre, u_light_forward) - u_near) * u_inv_range;
    gl_Position = u_view_proj * world;
}
