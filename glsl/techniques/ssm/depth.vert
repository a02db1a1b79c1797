#version 450 core
// `ssm` occluder and receiver maps: position from the light's centre, linear depth
// (distance along the light's forward axis - near) / (far - near). With PEEL (receiver layers,
// peel.frag) also the world position and normal.
#ifndef PEEL
#define PEEL 0
#endif
layout(location = 0) in vec3 a_position;
uniform mat4 u_model;
uniform mat4 u_view_proj;
uniform vec3 u_light_centre;
uniform vec3 u_light_forward;
uniform float u_near;
uniform float u_inv_range;  // 1 / (far - near)

out float v_depth;
#if PEEL
layout(location = 1) in vec3 a_normal;
uniform mat3 u_normal_matrix;
out vec3 v_world;
out vec3 v_normal;
#endif

void main() {
    vec4 world = u_model * vec4(a_position, 1.0);
    v_depth = (dot(world.xyz - u_light_centre, u_light_forward) - u_near) * u_inv_range;
#if PEEL
    v_world = world.xyz;
    v_normal = u_normal_matrix * a_normal;
#endif
    gl_Position = u_view_proj * world;
}
