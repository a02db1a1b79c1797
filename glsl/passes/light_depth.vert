#version 450 core
// Caster (or receiver) depth seen from a rect light, for every light depth map. SAMPLE_VIEWS 1:
// shadow maps from points on the light, one layer of an array per instance (u_views, linear
// depth of the view; gl_Layer from the vertex shader unless VERTEX_LAYER is 0). SAMPLE_VIEWS 0:
// one view from the light's centre through u_view_proj, depth (distance along the light's
// forward axis - u_near) * u_inv_range, or the distance itself with DISTANCE; with PEEL also
// the world position and normal (receiver layers, techniques/ssm/peel.frag).
#ifndef SAMPLE_VIEWS
#define SAMPLE_VIEWS 0
#endif
#ifndef VERTEX_LAYER
#define VERTEX_LAYER 0
#endif
#ifndef DISTANCE
#define DISTANCE 0
#endif
#ifndef PEEL
#define PEEL 0
#endif
#if SAMPLE_VIEWS && VERTEX_LAYER
#extension GL_ARB_shader_viewport_layer_array : require
#endif

layout(location = 0) in vec3 a_position;
uniform mat4 u_model;
out float v_depth;

#if SAMPLE_VIEWS
#include "common/sample_view.glsl"
uniform int u_view_base;  // index of this batch's first view in u_views

void main() {
    int index = u_view_base + gl_InstanceID;
    vec4 world = u_model * vec4(a_position, 1.0);
    v_depth = sampleLinearDepth(u_views[index], world.xyz);
    gl_Position = u_views[index].view_proj * world;
#if VERTEX_LAYER
    gl_Layer = gl_InstanceID;
#endif
}

#else
#include "common/light_frame.glsl"
uniform mat4 u_view_proj;
#if !DISTANCE
uniform float u_near;
uniform float u_inv_range;  // 1 / (far - near)
#endif
#if PEEL
layout(location = 1) in vec3 a_normal;
uniform mat3 u_normal_matrix;
out vec3 v_world;
out vec3 v_normal;
#endif

void main() {
    vec4 world = u_model * vec4(a_position, 1.0);
#if DISTANCE
    v_depth = dot(world.xyz - u_light_centre, u_light_forward);
#else
    v_depth = (dot(world.xyz - u_light_centre, u_light_forward) - u_near) * u_inv_range;
#endif
#if PEEL
    v_world = world.xyz;
    v_normal = u_normal_matrix * a_normal;
#endif
    gl_Position = u_view_proj * world;
}
#endif
