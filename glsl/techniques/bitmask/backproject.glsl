// `bitmask` back-projection (Schwarz & Stamminger, Bitmask Soft Shadows): every micropatch of
// an HSM level inside a search area that lies in front of the receiver is projected from the
// receiver onto the light; its light rectangle sets the bits of the light samples inside it
// (BITMASK 1, four half-plane table lookups) or adds its area (BITMASK 0). GAP_FILL 1 extends
// a micro-occluder towards a farther neighbour of its level so their projections leave no gap.
// MICRORECTS 1 back-projects microrects instead: the level's texel gives the reference point,
// the extent and depth come from their own mip chains (section 5.2), with the same extension.
// On a receiver that also casts, the light's part below its tangent plane counts as hidden
// (its own far side hides it, as `exact` finds): those samples are set too (BITMASK 1), or the
// area share above the plane scales the visibility (BITMASK 0). Needs search.glsl.
#include "techniques/bitmask/bindings.glsl"
#if MICRORECTS
// Level-0 texels x0, y0, x1, y1
layout(binding = BITMASK_UNIT_VISIBILITY_RECT_EXTENT) uniform sampler2D u_rect_extent;
layout(binding = BITMASK_UNIT_VISIBILITY_RECT_DEPTH) uniform sampler2D u_rect_depth;
#endif
#if BITMASK
// Rows 0-1: x >= u words, rows 2-3: y >= v
layout(binding = BITMASK_UNIT_VISIBILITY_MASKS) uniform usampler2D u_masks;
// Sample k at texel (k, 0): (u, v)
layout(binding = BITMASK_UNIT_VISIBILITY_SAMPLES) uniform sampler2D u_samples;
uniform int u_mask_resolution;
uniform float u_sample_count;
#else
#include "common/light_horizon.glsl"
#endif

// The light-plane coordinate of the ray from receiver coordinate P (depth PZ) through window
// coordinate W at distance Z: z (w pz - p) / (pz - z).
float onLight(float w, float p, float pz, float z) { return z * (w * pz - p) / (pz - z); }

#if BITMASK
// Visibility from an occlusion bitmask of u_sample_count bits in two halves.
float maskVisibility(uvec4 m0, uvec4 m1) {
    uvec4 bits = uvec4(bitCount(m0) + bitCount(m1));
    return 1.0 - float(bits.x + bits.y + bits.z + bits.w) / u_sample_count;
}
#endif

#if BITMASK
// The samples below the tangent plane HORIZON (receiverAt()), ORed into M0, M1 (bit k of the
// 256 = word k / 32, words 0-3 in M0).
void addBelowHorizon(vec3 horizon, inout uvec4 m0, inout uvec4 m1) {
    if (!crossesHorizon(horizon)) return;
    int n = int(u_sample_count);
    for (int k = 0; k < n; ++k) {
        vec2 s = texelFetch(u_samples, ivec2(k, 0), 0).xy;
        if (horizon.x + dot(horizon.yz, s) >= 0.0) continue;
        uint bit = 1u << uint(k & 31);
        int w = k >> 5;
        if (w < 4)
            m0[w] |= bit;
        else
            m1[w - 4] |= bit;
    }
}
#endif

// The visibility of a receiver with no micro-occluder in front: the light above HORIZON.
float litVisibility(vec3 horizon) {
#if BITMASK
    uvec4 m0 = uvec4(0u), m1 = uvec4(0u);
    addBelowHorizon(horizon, m0, m1);
    return maskVisibility(m0, m1);
#else
    return horizonArea(horizon.x, horizon.y, horizon.z);
#endif
}

#if MICROQUADS
#include "techniques/bitmask/microquads.glsl"
#endif

// The distance of micro-occluder (X, Y) of LEVEL: its microrect's or its micropatch's.
float occluderDepth(ivec2 xy, int level) {
#if MICRORECTS
    return texelFetch(u_rect_depth, xy, level).r;
#else
    return texelFetch(u_hsm, xy, level).r;
#endif
}

#if BITMASK
int maskIndex(float u) {
    return clamp(int(ceil(u * float(u_mask_resolution) - 0.5)), 0, u_mask_resolution);
}
#endif

// Back-projects the micro-occluders of LEVEL in AREA (level-0 texels) for receiver P (tangent
// plane HORIZON); returns visibility, COUNT = micro-occluders back-projected.
float backproject(vec3 p, vec3 horizon, float pz, vec4 area, int level, out int count) {
#if MICROQUADS
    return backprojectQuads(p, horizon, pz, area, level, count);
#endif
    count = 0;
    int n = u_map_size >> level;
    ivec4 r = levelRange(area, level, 1);
    vec2 t = u_texel * float(1 << level), scale = 0.5 / u_light_half;
#if BITMASK
    uvec4 m0 = uvec4(0u), m1 = uvec4(0u);
    addBelowHorizon(horizon, m0, m1);
#else
    float occluded = 0.0;
#endif
    for (int y = r.y; y <= r.w; ++y)
        for (int x = r.x; x <= r.z; ++x) {
            float zo = occluderDepth(ivec2(x, y), level);
            if (zo >= pz) continue;
            ++count;
#if MICRORECTS
            vec4 e = texelFetch(u_rect_extent, ivec2(x, y), level);
            vec2 w0 = u_win_lo + e.xy * u_texel, w1 = u_win_lo + (e.zw + 1.0) * u_texel;
#else
            vec2 w0 = u_win_lo + vec2(x, y) * t, w1 = w0 + t;
#endif
            vec2 l0 = vec2(onLight(w0.x, p.x, p.z, zo), onLight(w0.y, p.y, p.z, zo));
            vec2 l1 = vec2(onLight(w1.x, p.x, p.z, zo), onLight(w1.y, p.y, p.z, zo));
#if GAP_FILL
            float zl = x > 0 ? occluderDepth(ivec2(x - 1, y), level) : pz;
            float zr = x < n - 1 ? occluderDepth(ivec2(x + 1, y), level) : pz;
            float zd = y > 0 ? occluderDepth(ivec2(x, y - 1), level) : pz;
            float zu = y < n - 1 ? occluderDepth(ivec2(x, y + 1), level) : pz;
            if (zl > zo && zl < pz) l0.x = min(l0.x, onLight(w0.x, p.x, p.z, zl));
            if (zr > zo && zr < pz) l1.x = max(l1.x, onLight(w1.x, p.x, p.z, zr));
            if (zd > zo && zd < pz) l0.y = min(l0.y, onLight(w0.y, p.y, p.z, zd));
            if (zu > zo && zu < pz) l1.y = max(l1.y, onLight(w1.y, p.y, p.z, zu));
#endif
            vec2 uv0 = clamp(l0 * scale + 0.5, 0.0, 1.0), uv1 = clamp(l1 * scale + 0.5, 0.0, 1.0);
            if (uv0.x >= uv1.x || uv0.y >= uv1.y) continue;
#if BITMASK
            int x0 = maskIndex(uv0.x), x1 = maskIndex(uv1.x);
            int y0 = maskIndex(uv0.y), y1 = maskIndex(uv1.y);
            m0 |= texelFetch(u_masks, ivec2(x0, 0), 0) & ~texelFetch(u_masks, ivec2(x1, 0), 0) &
                  texelFetch(u_masks, ivec2(y0, 2), 0) & ~texelFetch(u_masks, ivec2(y1, 2), 0);
            m1 |= texelFetch(u_masks, ivec2(x0, 1), 0) & ~texelFetch(u_masks, ivec2(x1, 1), 0) &
                  texelFetch(u_masks, ivec2(y0, 3), 0) & ~texelFetch(u_masks, ivec2(y1, 3), 0);
#else
            occluded += (uv1.x - uv0.x) * (uv1.y - uv0.y);
#endif
        }
#if BITMASK
    return maskVisibility(m0, m1);
#else
    return horizonArea(horizon.x, horizon.y, horizon.z) * (1.0 - min(occluded, 1.0));
#endif
}
