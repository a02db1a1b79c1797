#version 450 core
// `bitmask` microrects (Schwarz & Stamminger 5.2): level k + 1 from level k by the greedy
// two-pass merge, both passes evaluated per output texel. Microrect M at (X, Y) keeps the
// reference point A = (2X, 2Y) of level k. Pass 1 merges its positive neighbours B (2X+1, 2Y)
// and D (2X, 2Y+1) when their depth is nearer A's than that of their other even neighbour, and
// the diagonal E (2X+1, 2Y+1) when the merged extent contains E's. Pass 2 takes the negative
// neighbours (2X-1, 2Y), (2X, 2Y-1), (2X-1, 2Y-1) that their own pass 1 left. Extent: the
// bounding rectangle of the merged extents (level-0 texels, inclusive; x0 > x1 = no caster);
// depth: their minimum, beside the farthest caster texel merged (backproject.glsl splits a
// microrect whose two lie apart: section 5.2's minimum alone puts a far caster merged with a
// near one at the near one's depth), the minimum marked where they do (split_flag.glsl).
// Level 1 (u_from_hsm = 1) merges the HSM's level-0 texels, the level-0 micropatches, which are
// not stored. The 14 depths the merge reads are loaded once, and a
// texel without caster (depth u_empty) has no extent to load. OWN_IDS 1: each microrect's
// object id too, that of its nearest texel (-1: none), and the nearest distance of the texels
// it merged of other objects (u_empty: none), so a receiver of that object can tell what else
// lies under it.
#include "techniques/bitmask/bindings.glsl"
#include "techniques/bitmask/split_flag.glsl"
#ifndef OWN_IDS
#define OWN_IDS 0
#endif
layout(local_size_x = 8, local_size_y = 8) in;
layout(rg32f, binding = BITMASK_IMAGE_MICRORECTS_HSM0) uniform readonly image2D u_hsm0;
layout(rgba32f, binding = BITMASK_IMAGE_MICRORECTS_EXTENT_IN) uniform readonly image2D u_extent_in;
// (nearest, farthest) caster texel merged
layout(rg32f, binding = BITMASK_IMAGE_MICRORECTS_DEPTH_IN) uniform readonly image2D u_depth_in;
layout(rgba32f,
       binding = BITMASK_IMAGE_MICRORECTS_EXTENT_OUT) uniform writeonly image2D u_extent_out;
layout(rg32f, binding = BITMASK_IMAGE_MICRORECTS_DEPTH_OUT) uniform writeonly image2D u_depth_out;
#if OWN_IDS
// (object id, the nearest distance of other objects' texels merged)
layout(rg32f, binding = BITMASK_IMAGE_MICRORECTS_OWNERS_IN) uniform readonly image2D u_owners_in;
layout(rg32f,
       binding = BITMASK_IMAGE_MICRORECTS_OWNERS_OUT) uniform writeonly image2D u_owners_out;
#endif
uniform int u_from_hsm;
uniform float u_empty;  // the distance of texels without casters

const vec4 kNone = vec4(1e9, 1e9, -1e9, -1e9);
ivec2 g_size;       // level k's size
ivec2 g_a;          // the reference point A in level k
float g_depth[25];  // level k's depths at A + (-2..2, -2..2), row-major; u_empty outside
float g_far[25];    // and their farthest caster texels (0: none)
#if OWN_IDS
int g_id[25];       // and their object ids (-1 outside)
float g_other[25];  // and their other objects' nearest distances
#endif

int slot(ivec2 o) {
    return (o.y + 2) * 5 + o.x + 2;
}
bool inside(ivec2 o) {
    ivec2 q = g_a + o;
    return all(greaterThanEqual(q, ivec2(0))) && all(lessThan(q, g_size));
}
void load(ivec2 o) {
    ivec2 q = g_a + o;
    vec2 z = vec2(u_empty, 0.0);
    if (inside(o)) z = u_from_hsm == 1 ? imageLoad(u_hsm0, q).rr : imageLoad(u_depth_in, q).rg;
    g_depth[slot(o)] = z.x;
    g_far[slot(o)] = z.x < u_empty ? z.y : 0.0;
#if OWN_IDS
    vec2 owner = z.x < u_empty ? imageLoad(u_owners_in, q).rg : vec2(-1.0, u_empty);
    g_id[slot(o)] = int(owner.x);
    g_other[slot(o)] = owner.y;
#endif
}
float depthAt(ivec2 o) {
    return g_depth[slot(o)];
}
// A texel's extent; none where it holds no caster (outside the level too).
vec4 extentAt(ivec2 o) {
    if (depthAt(o) >= u_empty) return kNone;
    ivec2 q = g_a + o;
    return u_from_hsm == 1 ? vec4(q, q) : imageLoad(u_extent_in, q);
}
vec4 unite(vec4 a, vec4 b) {
    return vec4(min(a.xy, b.xy), max(a.zw, b.zw));
}
bool contains(vec4 outer, vec4 e) {
    return e.x > e.z ||
           (all(lessThanEqual(outer.xy, e.xy)) && all(greaterThanEqual(outer.zw, e.zw)));
}
// |a - b|, infinite when either has no caster.
float gap(float a, float b) {
    return a >= u_empty || b >= u_empty ? 1e30 : abs(a - b);
}
// Whether the odd texel Q between even texels LO and HI merges with LO (pass 1 of LO).
bool mergesDown(ivec2 q, ivec2 lo, ivec2 hi) {
    float z = depthAt(q);
    return gap(z, depthAt(lo)) <= gap(z, depthAt(hi));
}

int idAt(ivec2 o) {
#if OWN_IDS
    return g_id[slot(o)];
#else
    return -1;
#endif
}
float otherAt(ivec2 o) {
#if OWN_IDS
    return g_other[slot(o)];
#else
    return u_empty;
#endif
}

struct Merged {
    vec4 extent;
    float depth;
    float far;    // the farthest caster texel's depth (0: none)
    int id;       // the nearest texel's object
    float other;  // the nearest distance of the texels of other objects
};
void take(inout Merged m, ivec2 q) {
    if (!inside(q)) return;
    m.extent = unite(m.extent, extentAt(q));
    m.far = max(m.far, g_far[slot(q)]);
    // The nearer of the two gives the id; the farther adds its texels of other objects: all of
    // them where its own id differs (its nearest among them), else those of its own others.
    float zq = depthAt(q), oq = otherAt(q);
    int iq = idAt(q);
    if (zq < m.depth) {
        m.other = min(oq, iq == m.id ? m.other : m.depth);
        m.id = iq;
        m.depth = zq;
    } else {
        m.other = min(m.other, iq == m.id ? oq : zq);
    }
}
// Pass 1 of the microrect with reference point A + O: A, B and D by depth, E by containment,
// or whatever its extent where no microrect at A + O + (2, 2) would take it in pass 2 (the
// level's last row or column): left there, a caster on the map's top or right edge, where the
// light's window puts the casters' bounds, lost texels at every coarser level.
Merged firstPass(ivec2 o) {
    Merged m = Merged(extentAt(o), depthAt(o), g_far[slot(o)], idAt(o), otherAt(o));
    if (mergesDown(o + ivec2(1, 0), o, o + ivec2(2, 0))) take(m, o + ivec2(1, 0));
    if (mergesDown(o + ivec2(0, 1), o, o + ivec2(0, 2))) take(m, o + ivec2(0, 1));
    if (inside(o + 1) && (contains(m.extent, extentAt(o + 1)) || !inside(o + 2)))
        take(m, o + 1);
    return m;
}

// The depths that the merge of A reads: pass 1 of A and of A - (2, 2), and pass 2's
// neighbours.
bool loadDepths() {
    const ivec2 kRead[14] =
        ivec2[](ivec2(0, 0), ivec2(1, 0), ivec2(2, 0), ivec2(0, 1), ivec2(0, 2), ivec2(1, 1),
                ivec2(-1, 0), ivec2(-2, 0), ivec2(0, -1), ivec2(0, -2), ivec2(-2, -2),
                ivec2(-1, -2), ivec2(-2, -1), ivec2(-1, -1));
    bool any_caster = false;
    for (int i = 0; i < 14; ++i) {
        load(kRead[i]);
        any_caster = any_caster || depthAt(kRead[i]) < u_empty;
    }
    return any_caster;
}

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, imageSize(u_extent_out)))) return;
    g_size = u_from_hsm == 1 ? imageSize(u_hsm0) : imageSize(u_extent_in);
    g_a = 2 * p;
    if (!loadDepths()) {
        imageStore(u_extent_out, p, kNone);
        imageStore(u_depth_out, p, vec4(u_empty, 0.0, 0.0, 0.0));
#if OWN_IDS
        imageStore(u_owners_out, p, vec4(-1.0, u_empty, 0.0, 0.0));
#endif
        return;
    }
    Merged m = firstPass(ivec2(0));
    const ivec2 left = ivec2(-1, 0), down = ivec2(0, -1);
    if (g_a.x > 0 && !mergesDown(left, left - ivec2(1, 0), ivec2(0))) take(m, left);
    if (g_a.y > 0 && !mergesDown(down, down - ivec2(0, 1), ivec2(0))) take(m, down);
    if (g_a.x > 0 && g_a.y > 0) {
        const ivec2 diagonal = ivec2(-1);
        if (!contains(firstPass(ivec2(-2)).extent, extentAt(diagonal))) take(m, diagonal);
    }
    imageStore(u_extent_out, p, m.extent);
    imageStore(u_depth_out, p, vec4(markSplit(m.depth, m.far), m.far, 0.0, 0.0));
#if OWN_IDS
    imageStore(u_owners_out, p, vec4(float(m.id), m.other, 0.0, 0.0));
#endif
}
