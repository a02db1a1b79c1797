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

#if MICRORECTS
// The distances of the nearest and the farthest caster texel that microrect (X, Y) of LEVEL
// (> 0) of LAYER merged (microrects.comp), in one fetch.
vec2 occluderDepths(int layer, ivec2 xy, int level) {
#if LAYERS == 2
    if (layer == 1) return texelFetch(u_far_rect_depth, xy, level).rg;
#endif
    return texelFetch(u_rect_depth, xy, level).rg;
}
#endif

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

#if GAP_FILL
// Light rectangle L (lightRect()) of micro-occluder W at distance ZO, seen from P (biased depth
// PZ), extended towards the neighbours it joins() at distances Z (left, right, below, above).
vec4 fillGaps(vec3 p, vec4 w, float zo, vec4 z, float pz, vec4 l) {
    if (joins(zo, z.x, pz)) l.x = min(l.x, onLight(w.x, p.x, p.z, z.x));
    if (joins(zo, z.y, pz)) l.z = max(l.z, onLight(w.z, p.x, p.z, z.y));
    if (joins(zo, z.z, pz)) l.y = min(l.y, onLight(w.y, p.y, p.z, z.z));
    if (joins(zo, z.w, pz)) l.w = max(l.w, onLight(w.w, p.y, p.z, z.w));
    return l;
}
#endif

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

// The light-plane rectangle (x0, y0, x1, y1) that micro-occluder W (window rectangle) at
// distance ZO hides from receiver P.
vec4 lightRect(vec3 p, vec4 w, float zo) {
    return vec4(onLight(w.x, p.x, p.z, zo), onLight(w.y, p.y, p.z, zo),
                onLight(w.z, p.x, p.z, zo), onLight(w.w, p.y, p.z, zo));
}

// Adds light-plane rectangle L (lightRect()) to C: the light samples inside it, or its area.
void cover(vec4 l, inout Coverage c) {
    vec2 scale = 0.5 / u_light_half;
    vec2 uv0 = clamp(l.xy * scale + 0.5, 0.0, 1.0);
    vec2 uv1 = clamp(l.zw * scale + 0.5, 0.0, 1.0);
    if (uv0.x >= uv1.x || uv0.y >= uv1.y) return;
#if BITMASK
    int x0 = 2 * maskIndex(uv0.x), x1 = 2 * maskIndex(uv1.x);
    int y0 = 2 * (maskIndex(uv0.y) + u_mask_resolution + 1);
    int y1 = 2 * (maskIndex(uv1.y) + u_mask_resolution + 1);
    c.m0 |= b_masks[x0] & ~b_masks[x1] & b_masks[y0] & ~b_masks[y1];
    c.m1 |= b_masks[x0 + 1] & ~b_masks[x1 + 1] & b_masks[y0 + 1] & ~b_masks[y1 + 1];
#else
    c.occluded += (uv1.x - uv0.x) * (uv1.y - uv0.y);
#endif
}

#if MICRORECTS
#include "techniques/bitmask/split_flag.glsl"
// Splitting (`split`; not in the paper): a microrect takes the nearest depth of the casters it
// merged (5.2), so one that merged a far caster with a near one casts the far one's shadow from
// the near one's depth: too small, and displaced. A board floating between the light and a ball
// lightened the shadows of both on the floor below at coarse levels (random scene rand9803).
// Such a microrect (marked by microrects.comp: split_flag.glsl) gives way to the finer level's
// microrects whose reference points lie next to its own (those it can have merged: A - 1 .. A +
// 1 on both axes), each at its own depth, where that moves its shadow enough (splits()). With a
// bitmask a microrect back-projected twice costs only time (BITMASK 0 adds its area twice, as it
// does for overlapping microrects).
uniform float u_split;  // the light's share (of its side) a split must move; 0: no splitting
// The marked microrects a pixel takes per layer and level: more are back-projected whole. They
// wait until the level's rows are done (backprojectLayer()): a split's own loop inside the rows'
// loop made the pass 2.3x slower on llvmpipe at 1024 x 768 where nothing split (default scene),
// as a software rasteriser runs a branch's code for every pixel of its group, and a fetch of
// the farthest distance for every micro-occluder 1.3x.
const int kPendingSplits = 16;

// Whether the marked microrect W (window rectangle) that hides light rectangle L (lightRect())
// from P at its nearest depth should be split: back-projected from its farthest caster texel's
// distance ZF instead, one of L's sides would move by more than u_split of the light's side. A
// farthest texel behind the receiver's biased depth PZ counts as lying just in front of it: such
// a microrect's extent covers some of what does not shadow P.
bool splits(vec3 p, vec4 w, vec4 l, float zf, float pz) {
    vec4 far = lightRect(p, w, min(zf, pz * 0.999));
    vec4 moved = abs(far - l) * (0.5 / u_light_half).xyxy;
    return max(max(moved.x, moved.y), max(moved.z, moved.w)) > u_split;
}

// Back-projects micro-occluder Q of LEVEL of LAYER (window rectangle W at distance ZO, light
// rectangle L) into C, extended towards its neighbours with gap filling, as backprojectLayer()
// does inside its rows (which slide the neighbours' depths along instead of fetching them).
void backprojectOne(int layer, vec3 p, float pz, ivec2 q, int level, vec4 w, float zo, vec4 l,
                    inout Coverage c, inout int count) {
    ++count;
#if GAP_FILL
    int n = u_map_size >> level;
    float zl = q.x > 0 ? occluderDepth(layer, q - ivec2(1, 0), level) : pz;
    float zr = q.x < n - 1 ? occluderDepth(layer, q + ivec2(1, 0), level) : pz;
    l = fillGaps(p, w, zo, vec4(zl, zr, occluderColumn(layer, q, level).yz), pz, l);
#endif
    cover(l, c);
}

// Back-projects the marked microrect XY of LEVEL of LAYER, or where splits() says so, in its
// place the microrects of LEVEL - 1 whose reference points lie next to its own (see above), as
// backprojectLayer() does its own.
void backprojectMarked(int layer, vec3 p, vec4 plane, int own, float pz, ivec2 xy, int level,
                       inout Coverage c, inout int count) {
    vec2 t = u_texel * float(1 << level);
    vec2 z = occluderDepths(layer, xy, level);
    vec4 w = occluderWindow(layer, xy.x, xy.y, level, t);
    vec4 l = lightRect(p, w, z.x);
    if (!splits(p, w, l, z.y, pz)) {
        backprojectOne(layer, p, pz, xy, level, w, z.x, l, c, count);
        return;
    }
    int k1 = level - 1;
    ivec2 n = ivec2(u_map_size >> k1);
    t *= 0.5;
    for (int k = 0; k < 9; ++k) {
        ivec2 q = 2 * xy + ivec2(k % 3, k / 3) - 1;
        if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, n))) continue;
        float zo = occluderDepth(layer, q, k1);
        if (zo >= pz) continue;
        vec4 wq = occluderWindow(layer, q.x, q.y, k1, t);
#if GAP_FILL
        float owner = occluderColumn(layer, q, k1).w;
#else
        float owner = 0.0;
#endif
        if (ownSurface(plane, wq, zo) || ownObject(layer, q.x, q.y, k1, own, pz, owner)) continue;
        backprojectOne(layer, p, pz, q, k1, wq, zo, lightRect(p, wq, zo), c, count);
    }
}
#endif

// Back-projects the micro-occluders of LEVEL of LAYER in the texel range R (levelRange()) for
// receiver P (biased depth PZ) into C, but those ownSurface() finds of P's tangent plane PLANE
// and those ownObject() finds of its convex object OWN;
// COUNT += those back-projected. A row's depths slide along it (each texel read once; GAP_FILL
// reads its left and right neighbours from there), and with a bitmask the rows stop once every
// light sample is occluded; returns whether they did.
bool backprojectLayer(int layer, vec3 p, vec4 plane, int own, float pz, ivec4 r, int level,
                      inout Coverage c, inout int count) {
    int n = u_map_size >> level;
    vec2 t = u_texel * float(1 << level);
#if MICRORECTS
    ivec2 marked[kPendingSplits];  // marked microrects (split_flag.glsl), back-projected last
    int pending = 0;
#endif
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
#if MICRORECTS
                if (level > 0 && u_split > 0.0 && splitMarked(zo) && pending < kPendingSplits) {
                    marked[pending++] = ivec2(x, y);
                } else {
#else
                {
#endif
                    ++count;
                    vec4 l = lightRect(p, w, zo);
#if GAP_FILL
                    l = fillGaps(p, w, zo, vec4(zl, zr, co.yz), pz, l);
#endif
                    cover(l, c);
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
#if MICRORECTS
    for (int i = 0; i < pending; ++i)
        backprojectMarked(layer, p, plane, own, pz, marked[i], level, c, count);
#if BITMASK
    if (maskFull(c.m0, c.m1)) return true;
#endif
#endif
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
