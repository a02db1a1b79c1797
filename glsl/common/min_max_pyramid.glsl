// A min/max mip pyramid (RG: min, max per texel) of a light-centred map queried over an inclusive
// texel range of its level 0 with four fetches, and the search area that range comes from
// (include-only): `bitmask`'s HSM search and `adaptive`'s lit region.
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

// The search area of P (light frame, from its centre; P.z > 0) at distance Z: the pyramid from P
// to the light (half-size LIGHT_HALF) cut at Z, seen from the light's centre, in level-0 texels
// (x0, y0, x1, y1) of a map whose window starts at WIN_LO with TEXEL window units a texel;
// unclipped.
vec4 lightSearchArea(vec3 p, float z, vec2 light_half, vec2 win_lo, vec2 texel) {
    vec2 c = p.xy / p.z;
    vec2 h = light_half * (1.0 / z - 1.0 / p.z);
    return vec4((c - h - win_lo) / texel, (c + h - win_lo) / texel);
}

// Whether area A (level-0 texels) lies wholly outside a map of SIZE texels.
bool areaMissesMap(vec4 a, int size) {
    float n = float(size);
    return a.z < 0.0 || a.w < 0.0 || a.x >= n || a.y >= n;
}

#endif  // PENUMBRA_MIN_MAX_PYRAMID_GLSL
