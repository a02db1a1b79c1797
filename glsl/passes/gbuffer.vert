#version 450 core
// G-buffer: world position, normal, uv and view depth of every visible surface.
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec2 a_uv;

uniform mat4 u_model;
uniform mat3 u_normal_matrix;
uniform mat4 u_view;
uniform mat4 u_projection;

out vec3 v_world;
out vec3 v_normal;
out vec2 v_uv;
out float v_view_depth;

void main() {
    vec4 world = u_model * vec4(a_position, 1.0);
    vec4 view = u_view * world;
    v_world = world.xyz;
    v_normal = u_normal_matrix * a_normal;
    v_uv = a_uv;
    v_view_depth = -view.z;
    gl_Position = u_projection * view;
}
