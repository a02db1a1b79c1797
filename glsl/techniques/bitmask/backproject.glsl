// `bitmask` back-projection (Schwarz & Stamminger, Bitmask Soft Shadows): every micropatch of
// an HSM level inside a search area that lies in front of the receiver is projected from the
// receiver onto the light; its light rectangle sets the bits of the light samples inside it
// (BITMASK 1, four half-plane table lookups in a buffer) or adds its area (BITMASK 0). GAP_FILL 1
// extends a micro-occluder towards a farther neighbour of its level so their projections leave no
// gap. MICRORECTS 1 back-projects microrects instead: the level's texel gives the reference
// point, the extent and depth come from their own mip chains (section 5.2), with the same
// extension. LAYERS 2 back-projects the far layer's micro-occluders too (depth peeling, as
// Bavoil et al. 2008 add to back-projection): what the light's edges see under a caster's
// silhouette, which the map from its centre does not hold.
// On a receiver that also casts, the light's part below its tangent plane counts as hidden
// (its own far side hides it, as `exact` finds): those samples are set too (BITMASK 1), or the
// area share above the plane scales the visibility (BITMASK 0). Needs search.glsl.
#include "techniques/bitmask/bindings.glsl"
#if LAYERS == 2
// The far layer's (min, max) pyramid: its micropatches at level 0 (and all levels without
// microrects)
layout(binding = BITMASK_UNIT_VISIBILITY_FAR) uniform sampler2D u_far;
#endif
#ifndef OWN_IDS
#define OWN_IDS 0
#endif
#if OWN_IDS && !GAP_FILL
// Per layer, the owner of each micropatch (level 0) and microrect (levels 1..): the object id
// of its nearest texel (-1: none) and the nearest distance of the texels it merged of other
// objects (microrects.comp). With gap filling, its neighbour depths carry them packed.
layout(binding = BITMASK_UNIT_VISIBILITY_OWNERS) uniform sampler2D u_owners;
#if LAYERS == 2
layout(binding = BITMASK_UNIT_VISIBILITY_FAR_OWNERS) uniform sampler2D u_far_owners;
#endif
#endif
#if MICRORECTS
// Level-0 texels x0, y0, x1, y1
layout(binding = BITMASK_UNIT_VISIBILITY_RECT_EXTENT) uniform sampler2D u_rect_extent;
layout(binding = BITMASK_UNIT_VISIBILITY_RECT_DEPTH) uniform sampler2D u_rect_depth;
#if LAYERS == 2
layout(binding = BITMASK_UNIT_VISIBILITY_FAR_RECT_EXTENT) uniform sampler2D u_far_rect_extent;
layout(binding = BITMASK_UNIT_VISIBILITY_FAR_RECT_DEPTH) uniform sampler2D u_far_rect_depth;
#endif
#endif
#if BITMASK
// Mask i of x >= u at 2 i (words 0-3), 2 i + 1 (words 4-7); y >= v after them
layout(std430, binding = BITMASK_BINDING_VISIBILITY_MASKS) readonly buffer Masks {
    uvec4 b_masks[];
};
// Sample k at texel (k, 0): (u, v)
layout(binding = BITMASK_UNIT_VISIBILITY_SAMPLES) uniform sampler2D u_samples;
uniform int u_mask_resolution;
uniform float u_sample_count;
#else
#include "common/light_horizon.glsl"
#endif

#if GAP_FILL
// Per level, each micro-occluder's distance with those below and above it (neighbours.comp;
// one fetch for the three that gap filling reads): the map's, and the far layer's
layout(binding = BITMASK_UNIT_VISIBILITY_NEIGHBOURS) uniform sampler2D u_neighbours;
#if LAYERS == 2
layout(binding = BITMASK_UNIT_VISIBILITY_FAR_NEIGHBOURS) uniform sampler2D u_far_neighbours;
#endif

// Gap filling's reach (gap_ratio): a neighbour at least this many times farther is not joined
// (0: any farther one). Bridging a near caster's silhouette to a far caster beside it in the
// light's view assumes the far one continues behind the near one.
uniform float u_gap_ratio;

// Whether gap filling joins a micro-occluder at depth ZO to its neighbour at depth ZN, in front
// of the receiver at PZ.
bool joins(float zo, float zn, float pz) {
    return zn > zo && zn < pz && (u_gap_ratio <= 0.0 || zn < zo * u_gap_ratio);
}

// The distance of the micro-occluder at (X, Y) of LAYER's LEVEL with those of (X, Y - 1) and
// (X, Y + 1), farther than any receiver where the map ends, and its packed owner (OWN_IDS;
// neighbours.comp): (distance, below, above, owner).
vec4 occluderColumn(int layer, ivec2 xy, int level) {
#if LAYERS == 2
    if (layer == 1) return texelFetch(u_far_neighbours, xy, level);
#endif
    return texelFetch(u_neighbours, xy, level);
}
#endif

// The light-plane coordinate of the ray from receiver coordinate P (depth PZ) through window
// coordinate W at distance Z: z (w pz - p) / (pz - z).
float onLight(float w, float p, float pz, float z) {
    return z * (w * pz - p) / (pz - z);
}

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

// The distance of micro-occluder (X, Y) of LEVEL of depth layer LAYER (0 the map, 1 the far
// layer): its microrect's or its micropatch's (level 0 has no microrect texels: there they are
// the micropatches, the pyramid's level 0).
float occluderDepth(int layer, ivec2 xy, int level) {
#if LAYERS == 2
    if (layer == 1) {
#if MICRORECTS
        if (level > 0) return texelFetch(u_far_rect_depth, xy, level).r;
#endif
        return texelFetch(u_far, xy, level).r;
    }
#endif
#if MICRORECTS
    if (level > 0) return texelFetch(u_rect_depth, xy, level).r;
#endif
    return texelFetch(u_hsm, xy, level).r;
}

#if BITMASK
int maskIndex(float u) {
    return clamp(int(ceil(u * float(u_mask_resolution) - 0.5)), 0, u_mask_resolution);
}
#endif

// The window rectangle (lo, hi) of micro-occluder (X, Y) of LEVEL of LAYER, whose texel is T
// wide.
vec4 occluderWindow(int layer, int x, int y, int level, vec2 t) {
#if MICRORECTS
    if (level > 0) {
#if LAYERS == 2
        vec4 e = layer == 1 ? texelFetch(u_far_rect_extent, ivec2(x, y), level)
                            : texelFetch(u_rect_extent, ivec2(x, y), level);
#else
        vec4 e = texelFetch(u_rect_extent, ivec2(x, y), level);
#endif
        return vec4(u_win_lo + e.xy * u_texel, u_win_lo + (e.zw + 1.0) * u_texel);
    }
#endif
    vec2 w0 = u_win_lo + vec2(x, y) * t;
    return vec4(w0, w0 + t);
}

#if BITMASK
// Whether every light sample of M0, M1 is occluded: nothing more can change the visibility.
bool maskFull(uvec4 m0, uvec4 m1) {
    return maskVisibility(m0, m1) <= 0.0;
}
#endif

// What the micro-occluders back-projected so far hide of the light: a bitmask (BITMASK 1) or
// their summed area.
struct Coverage {
    uvec4 m0, m1;    // bit k of the 256 samples: word k / 32, words 0-3 in m0
    float occluded;  // BITMASK 0
};

// Whether the micro-occluder W (window rectangle, at distance 1) at depth ZO could be the flat
// receiver face's own (its tangent plane PLANE, receiverAt(); none where 0): one lies at the
// face's nearest depth over W, so it meets the plane at one corner (within a level-0 texel's
// span) and rises above it at most by the plane's depth span over W, ZO (|n.x| w + |n.y| h), at
// the others. Such a one hides only light that the face's far side hides (the horizon's samples,
// set already) or a sliver above it. Left in, coarse levels shaded faces nearly edge-on to the
// light in bands, which an offset along the normal had cleared by moving the receiver sideways.
// A caster wholly above the plane is kept, however near.
bool ownSurface(vec4 plane, vec4 w, float zo) {
    if (plane.xyz == vec3(0.0)) return false;
    vec2 x = plane.x * w.xz, y = plane.y * w.yw;  // each corner's height: (x + y + n.z) zo - d
    float highest = (max(x.x, x.y) + max(y.x, y.y) + plane.z) * zo - plane.w;
    float lowest = (min(x.x, x.y) + min(y.x, y.y) + plane.z) * zo - plane.w;
    vec2 n = abs(plane.xy);
    return lowest <= dot(n, u_texel) * zo && highest <= dot(n, w.zw - w.xy) * zo;
}

// Whether micro-occluder (X, Y) of LEVEL of LAYER is the receiver's convex object OWN
// (receiverAt()) and what else it merged lies behind the receiver's biased depth PZ. A convex
// object hides from a point of its surface only the light below the tangent plane there (the
// horizon's samples, set already), so such micro-occluders are left out whatever their level:
// a coarse one takes the object's nearest depth over a block, which lies far in front of most
// of the surface it covers (a box's top edge over its face). One whose block holds another
// caster in front of the receiver is kept. OWNER: with gap filling, its owner as its neighbour
// depths pack it (occluderColumn()), which spares a fetch in the loop: on a software rasteriser
// every pixel pays a branch's fetch.
bool ownObject(int layer, int x, int y, int level, int own, float pz, float owner) {
#if OWN_IDS
    if (own < 0) return false;
#if GAP_FILL
    uint b = floatBitsToUint(owner);
    return int(b & 0xFFu) == own + 1 && uintBitsToFloat(b & ~0xFFu) >= pz;
#else
#if !MICRORECTS
    if (level > 0) return false;  // coarse micropatches carry no owners
#endif
#if LAYERS == 2
    vec2 o = layer == 1 ? texelFetch(u_far_owners, ivec2(x, y), level).rg
                        : texelFetch(u_owners, ivec2(x, y), level).rg;
#else
    vec2 o = texelFetch(u_owners, ivec2(x, y), level).rg;
#endif
    return int(o.x) == own && o.y >= pz;
#endif
#else
    return false;
#endif
}

// Back-projects the micro-occluders of LEVEL of LAYER in the texel range R (levelRange()) for
// receiver P (biased depth PZ) into C, but those ownSurface() finds of P's tangent plane PLANE
// and those ownObject() finds of its convex object OWN;
// COUNT += those back-projected. A row's depths slide along it (each texel read once; GAP_FILL
// reads its left and right neighbours from there), and with a bitmask the rows stop once every
// light sample is occluded; returns whether they did.
bool backprojectLayer(int layer, vec3 p, vec4 plane, int own, float pz, ivec4 r, int level,
                      inout Coverage c, inout int count) {
    int n = u_map_size >> level;
    vec2 t = u_texel * float(1 << level), scale = 0.5 / u_light_half;
    for (int y = r.y; y <= r.w; ++y) {
        float zl = r.x > 0 ? occluderDepth(layer, ivec2(r.x - 1, y), level) : pz;
#if GAP_FILL
        vec4 co = occluderColumn(layer, ivec2(r.x, y), level);
        float zo = co.x;
#else
        float zo = occluderDepth(layer, ivec2(r.x, y), level);
#endif
        for (int x = r.x; x <= r.z; ++x) {
#if GAP_FILL
            vec4 cr =
                x < n - 1 ? occluderColumn(layer, ivec2(x + 1, y), level) : vec4(vec3(pz), 0.0);
            float zr = cr.x;
#else
            float zr = x < n - 1 ? occluderDepth(layer, ivec2(x + 1, y), level) : pz;
#endif
            vec4 w = zo < pz ? occluderWindow(layer, x, y, level, t) : vec4(0.0);
#if GAP_FILL
            float owner = co.w;
#else
            float owner = 0.0;
#endif
            if (zo < pz && !ownSurface(plane, w, zo) &&
                !ownObject(layer, x, y, level, own, pz, owner)) {
                ++count;
                vec2 l0 = vec2(onLight(w.x, p.x, p.z, zo), onLight(w.y, p.y, p.z, zo));
                vec2 l1 = vec2(onLight(w.z, p.x, p.z, zo), onLight(w.w, p.y, p.z, zo));
#if GAP_FILL
                float zd = co.y, zu = co.z;
                if (joins(zo, zl, pz)) l0.x = min(l0.x, onLight(w.x, p.x, p.z, zl));
                if (joins(zo, zr, pz)) l1.x = max(l1.x, onLight(w.z, p.x, p.z, zr));
                if (joins(zo, zd, pz)) l0.y = min(l0.y, onLight(w.y, p.y, p.z, zd));
                if (joins(zo, zu, pz)) l1.y = max(l1.y, onLight(w.w, p.y, p.z, zu));
#endif
                vec2 uv0 = clamp(l0 * scale + 0.5, 0.0, 1.0);
                vec2 uv1 = clamp(l1 * scale + 0.5, 0.0, 1.0);
                if (uv0.x < uv1.x && uv0.y < uv1.y) {
#if BITMASK
                    int x0 = 2 * maskIndex(uv0.x), x1 = 2 * maskIndex(uv1.x);
                    int y0 = 2 * (maskIndex(uv0.y) + u_mask_resolution + 1);
                    int y1 = 2 * (maskIndex(uv1.y) + u_mask_resolution + 1);
                    c.m0 |= b_masks[x0] & ~b_masks[x1] & b_masks[y0] & ~b_masks[y1];
                    c.m1 |= b_masks[x0 + 1] & ~b_masks[x1 + 1] & b_masks[y0 + 1] &
                            ~b_masks[y1 + 1];
#else
                    c.occluded += (uv1.x - uv0.x) * (uv1.y - uv0.y);
#endif
                }
            }
            zl = zo;
            zo = zr;
#if GAP_FILL
            co = cr;
#endif
        }
#if BITMASK
        if (maskFull(c.m0, c.m1)) return true;
#endif
    }
    return false;
}

#if MICROQUADS
#include "techniques/bitmask/microquads.glsl"
#endif

#if LAYERS == 2
// Whether a far-layer micro-occluder of LEVEL in the texel range R (levelRange()) can lie in
// front of depth PZ: the far pyramid's min over R grown by a texel of LEVEL on each side (a
// microrect's depth is the min of texels it merged, which reach into the texel below it,
// microrects.comp). Where none can, its loop would read every texel of R for nothing: on a
// caster's lit side, whose own far side lies behind it.
bool farLayerInFront(ivec4 r, int level, float pz) {
    int n = u_map_size >> level;
    ivec4 g = clamp(r + ivec4(-1, -1, 1, 1), ivec4(0), ivec4(n - 1));
    ivec4 r0 = ivec4(g.xy << level, ((g.zw + 1) << level) - 1);
    return pyramidRange(u_far, r0, hsmQueryLevel(r0)).x < pz;
}
#endif

// Back-projects the micro-occluders of LEVEL in AREA (level-0 texels) for receiver P (tangent
// plane HORIZON; PLANE as receiverAt()'s): the map's (micropatches, microrects or microquads),
// then with LAYERS 2 the far layer's micropatches (microrects with microrects) of the same
// texels, unless the map's already hide the whole light or none of the far layer's lies in front
// (farLayerInFront()); returns visibility, COUNT = micro-occluders back-projected.
float backproject(vec3 p, vec3 horizon, vec4 plane, int own, float pz, vec4 area, int level,
                  out int count) {
    count = 0;
    Coverage c = Coverage(uvec4(0u), uvec4(0u), 0.0);
#if BITMASK
    addBelowHorizon(horizon, c.m0, c.m1);
#endif
    ivec4 r = levelRange(area, level, 1);
#if MICROQUADS
    bool full = addQuads(p, pz, area, level, c.m0, c.m1, count);
#else
    bool full = backprojectLayer(0, p, plane, own, pz, r, level, c, count);
#endif
#if LAYERS == 2
    if (!full && farLayerInFront(r, level, pz))
        backprojectLayer(1, p, plane, own, pz, r, level, c, count);
#endif
#if BITMASK
    return maskVisibility(c.m0, c.m1);
#else
    return horizonArea(horizon.x, horizon.y, horizon.z) * (1.0 - min(c.occluded, 1.0));
#endif
}
