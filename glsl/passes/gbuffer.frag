#version 450 core
// G-buffer targets: position (w = 1 on geometry), normal + view depth, linear albedo, object id,
// and the geometric normal: the plane of the drawn triangle, facing the side seen (w: 1 where
// that is the triangle's back).
#include "common/bindings.glsl"
in vec3 v_world;
in vec3 v_normal;
in vec2 v_uv;
in float v_view_depth;

// TEXTURED 1: the variant for materials with a base colour texture (GpuScene::draw picks it
// per draw; a branch on a uniform ran the lookup for every pixel on llvmpipe, a quarter of this
// pass at 1024 x 768).
#ifndef TEXTURED
#define TEXTURED 0
#endif
uniform vec4 u_base_color;
uniform int u_object_id;
#if TEXTURED
layout(binding = UNIT_BASE_TEXTURE) uniform sampler2D u_base_texture;
#endif

layout(location = 0) out vec4 o_position;
layout(location = 1) out vec4 o_normal;
layout(location = 2) out vec4 o_albedo;
layout(location = 3) out int o_id;
layout(location = 4) out vec4 o_geometric_normal;

void main() {
    vec3 n = normalize(v_normal);
    if (!gl_FrontFacing) n = -n;  // two-sided surfaces (planes seen from below)
    vec4 albedo = u_base_color;
#if TEXTURED
    albedo *= texture(u_base_texture, v_uv);  // sRGB decoded by GL
#endif
    o_position = vec4(v_world, 1.0);
    o_normal = vec4(n, v_view_depth);
    o_albedo = vec4(albedo.rgb, 1.0);
    o_id = u_object_id;
    // The derivatives of the interpolated position span the triangle's plane (helper
    // invocations extrapolate the same triangle); its normal is turned to the shading normal's
    // side, which already faces the viewer.
    vec3 g = cross(dFdx(v_world), dFdy(v_world));
    float len = length(g);
    g = len > 0.0 ? g / len : n;
    o_geometric_normal = vec4(dot(g, n) < 0.0 ? -g : g, gl_FrontFacing ? 0.0 : 1.0);
}
