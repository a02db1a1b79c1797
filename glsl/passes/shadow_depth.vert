#version 450 core
// Caster depth into one layer of a shadow-map array per instance (gl_Layer from the vertex
// shader), or into the attached layer when VERTEX_LAYER is 0.
#ifndef VERTEX_LAYER
#define VERTEX_LAYER 1
#endif
#if VERTEX_LAYER
#extension GL_ARB_shader_viewport_layer_array : require
#endif
#include "common/sample_view.glsl"

layout(location = 0) in vec3 a_position;
uniform mat4 u_model;
uniform int u_view_base;  // index of this batch's first view in u_views

out float v_depth;

void main() {
    int index = u_view_base + gl_InstanceID;
    vec4 world = u_model * vec4(a_position, 1.0);
    v_depth = sampleLinearDepth(u_views[index], world.xyz);
    gl_Position = u_views[index].view_proj * world;
#if VERTEX_LAYER
    gl_Layer = gl_InstanceID;
#endif
}
