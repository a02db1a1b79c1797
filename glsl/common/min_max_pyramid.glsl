// A min/max mip pyramid (RG: min, max per texel) queried over an inclusive texel range of its
// level 0 with four fetches (include-only): `bitmask`'s HSM search and `adaptive`'s lit region.
#ifndef PENUMBRA_MIN_MAX_PYRAMID_GLSL
#define PENUMBRA_MIN_MAX_PYRAMID_GLSL

vec2 combine4(vec2 a, vec2 b, vec2 c, vec2 d) {
    return vec2(min(min(a.x, b.x), min(c.x, d.x)), max(max(a.y, b.y), max(c.y, d.y)));
}

// The level (of LEVELS) at which the inclusive texel range R (level 0) spans at most 2 x 2
// texels.
int pyramidLevel(ivec4 r, int levels) {
    int k = 0;
    while (k < levels - 1 && ((r.z >> k) - (r.x >> k) > 1 || (r.w >> k) - (r.y >> k) > 1)) ++k;
    return k;
}

// The (min, max) over the inclusive texel range R (level 0) of a min/max PYRAMID, from its
// level K (pyramidLevel()).
vec2 pyramidRange(sampler2D pyramid, ivec4 r, int k) {
    ivec4 q = r >> k;
    return combine4(texelFetch(pyramid, q.xy, k).rg, texelFetch(pyramid, q.zy, k).rg,
                    texelFetch(pyramid, q.xw, k).rg, texelFetch(pyramid, q.zw, k).rg);
}

#endif  // PENUMBRA_MIN_MAX_PYRAMID_GLSL
