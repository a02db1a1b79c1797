#version 450 core
// `bitmask` MSSM (multi-scale shadow map): layer k holds, per texel (x, y), the (min, max)
// distance over [x, x + 2^k) x [y, y + 2^k) (clamped at the map's edge). Layer 0 is an HSM
// level (0 for the MSSM, a coarser one for the YSM's MSSM part). One dispatch writes layers
// u_layer and u_layer + 1 (when u_pair) from layer u_layer - 1: the 4 x 4 texels at offsets
// 0, h, 2h, 3h (h = 2^(u_layer - 1)) cover both, so a pass costs one dispatch for two layers.
// Each layer is bound as a 2D image of its own (depth_ranges.cpp): the layer below read-only
// (for the YSM's layer 1, the HSM level itself; its layer 0 is never written), the layers
// written write-only (on llvmpipe the array image read and written in place took 1.7x as long;
// texelFetch through samplers 4x, a shared-memory tile with a barrier 3x).
#include "techniques/bitmask/bindings.glsl"
layout(local_size_x = 8, local_size_y = 8) in;
layout(rg32f, binding = BITMASK_IMAGE_MSSM_BELOW) uniform readonly image2D u_below;
layout(rg32f, binding = BITMASK_IMAGE_MSSM) uniform writeonly image2D u_out;
layout(rg32f, binding = BITMASK_IMAGE_MSSM_NEXT) uniform writeonly image2D u_next;
uniform int u_layer;
uniform bool u_pair;

vec2 combine(vec2 a, vec2 b) { return vec2(min(a.x, b.x), max(a.y, b.y)); }

vec2 below(ivec2 p) { return imageLoad(u_below, p).rg; }

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = imageSize(u_below);
    if (any(greaterThanEqual(p, size))) return;
    if (u_layer == 0) {
        imageStore(u_out, p, vec4(below(p), 0.0, 0.0));
        return;
    }
    int h = 1 << (u_layer - 1);
    // Rows and columns at offsets 0, h (layer u_layer) and 2h, 3h (layer u_layer + 1),
    // clamped: a clamped texel's neighbourhood still lies inside [p, edge).
    ivec4 xs = min(p.x + ivec4(0, h, 2 * h, 3 * h), size.x - 1);
    ivec4 ys = min(p.y + ivec4(0, h, 2 * h, 3 * h), size.y - 1);
    vec2 near = combine(combine(below(ivec2(xs.x, ys.x)), below(ivec2(xs.y, ys.x))),
                        combine(below(ivec2(xs.x, ys.y)), below(ivec2(xs.y, ys.y))));
    imageStore(u_out, p, vec4(near, 0.0, 0.0));
    if (!u_pair) return;
    vec2 r = near;
    for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i)
            if (i >= 2 || j >= 2) r = combine(r, below(ivec2(xs[i], ys[j])));
    imageStore(u_next, p, vec4(r, 0.0, 0.0));
}
