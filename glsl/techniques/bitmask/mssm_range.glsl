// `bitmask`'s MSSM query: the exact (min, max) over an inclusive texel range of layer 0 from
// power-of-two neighbourhoods of one layer (include-only; search.glsl, the GL tests).
#ifndef PENUMBRA_MSSM_RANGE_GLSL
#define PENUMBRA_MSSM_RANGE_GLSL

#include "common/min_max_pyramid.glsl"

// The (min, max) over the inclusive texel range R of layer 0 of MSSM (layer k: per texel the
// range over its 2^k x 2^k neighbourhood): four overlapping neighbourhoods of the layer of R's
// longer extent cover it, exactly along that axis; along the shorter one they reach 2^k texels
// from its start (clamped at the map's edge). The top layer built is log2(size) - 2
// (depth_ranges.cpp): an extent wider than two of its neighbourhoods (up to the whole map,
// four) takes up to 4 x 4 of them, starting 2^k apart, the last ending at R's edge.
vec2 mssmRange(sampler2DArray mssm, ivec4 r) {
    int extent = max(r.z - r.x, r.w - r.y) + 1;
    int top = textureSize(mssm, 0).z - 1;
    int k = min(findMSB(extent), top);
    ivec2 hi = max(r.zw - ((1 << k) - 1), r.xy);
    if (findMSB(extent) <= top)
        return combine4(texelFetch(mssm, ivec3(r.xy, k), 0).rg,
                        texelFetch(mssm, ivec3(hi.x, r.y, k), 0).rg,
                        texelFetch(mssm, ivec3(r.x, hi.y, k), 0).rg,
                        texelFetch(mssm, ivec3(hi, k), 0).rg);
    vec2 range = texelFetch(mssm, ivec3(r.xy, k), 0).rg;
    for (int j = 0; j < 4; ++j) {
        int y = min(r.y + (j << k), hi.y);
        for (int i = 0; i < 4; ++i) {
            vec2 t = texelFetch(mssm, ivec3(min(r.x + (i << k), hi.x), y, k), 0).rg;
            range = vec2(min(range.x, t.x), max(range.y, t.y));
        }
    }
    return range;
}

#endif  // PENUMBRA_MSSM_RANGE_GLSL
