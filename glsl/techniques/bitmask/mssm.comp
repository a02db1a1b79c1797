#version 450 core
// `bitmask` MSSM (multi-scale shadow map): layer k holds, per texel (x, y), the (min, max)
// distance over [x, x + 2^k) x [y, y + 2^k) (clamped at the map's edge). Layer 0 is an HSM
// level (0 for the MSSM, a coarser one for the YSM's MSSM part). One dispatch writes layers
// u_layer and u_layer + 1 (when u_pair) from layer u_layer - 1: the 4 x 4 texels at offsets
// 0, h, 2h, 3h (h = 2^(u_layer - 1)) cover both, so a pass costs one dispatch for two layers.
// With u_from_hsm, the layers above 0 read the HSM level directly and layer 0 is never
// written: the YSM queries its MSSM part only for extents of 3 texels or more (layer >= 1).
#include "techniques/bitmask/bindings.glsl"
layout(local_size_x = 8, local_size_y = 8) in;
layout(rg32f, binding = BITMASK_IMAGE_MSSM_HSM_LEVEL) uniform readonly image2D u_hsm_level;
layout(rg32f, binding = BITMASK_IMAGE_MSSM) uniform image2DArray u_mssm;
uniform int u_layer;
uniform bool u_pair;
uniform bool u_from_hsm;

vec2 combine(vec2 a, vec2 b) { return vec2(min(a.x, b.x), max(a.y, b.y)); }

vec2 below(ivec2 p) {
    return u_from_hsm && u_layer == 1 ? imageLoad(u_hsm_level, p).rg
                                      : imageLoad(u_mssm, ivec3(p, u_layer - 1)).rg;
}

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = imageSize(u_mssm).xy;
    if (any(greaterThanEqual(p, size))) return;
    if (u_layer == 0) {
        imageStore(u_mssm, ivec3(p, 0), vec4(imageLoad(u_hsm_level, p).rg, 0.0, 0.0));
        return;
    }
    int h = 1 << (u_layer - 1);
    // Rows and columns at offsets 0, h (layer u_layer) and 2h, 3h (layer u_layer + 1),
    // clamped: a clamped texel's neighbourhood still lies inside [p, edge).
    ivec4 xs = min(p.x + ivec4(0, h, 2 * h, 3 * h), size.x - 1);
    ivec4 ys = min(p.y + ivec4(0, h, 2 * h, 3 * h), size.y - 1);
    vec2 near = combine(combine(below(ivec2(xs.x, ys.x)), below(ivec2(xs.y, ys.x))),
                        combine(below(ivec2(xs.x, ys.y)), below(ivec2(xs.y, ys.y))));
    imageStore(u_mssm, ivec3(p, u_layer), vec4(near, 0.0, 0.0));
    if (!u_pair) return;
    vec2 r = near;
    for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i)
            if (i >= 2 || j >= 2) r = combine(r, below(ivec2(xs[i], ys[j])));
    imageStore(u_mssm, ivec3(p, u_layer + 1), vec4(r, 0.0, 0.0));
}
