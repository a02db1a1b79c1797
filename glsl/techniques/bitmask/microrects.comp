#version 450 core
// `bitmask` microrects (Schwarz & Stamminger 5.2): level k + 1 from level k by the greedy
// two-pass merge, both passes evaluated per output texel. Microrect M at (X, Y) keeps the
// reference point A = (2X, 2Y) of level k. Pass 1 merges its positive neighbours B (2X+1, 2Y)
// and D (2X, 2Y+1) when their depth is nearer A's than that of their other even neighbour, and
// the diagonal E (2X+1, 2Y+1) when the merged extent contains E's. Pass 2 takes the negative
// neighbours (2X-1, 2Y), (2X, 2Y-1), (2X-1, 2Y-1) that their own pass 1 left. Extent: the
// bounding rectangle of the merged extents (level-0 texels, inclusive; x0 > x1 = no caster);
// depth: their minimum. Level 0 (u_from_hsm = 1): one micropatch per HSM level-0 texel.
#include "techniques/bitmask/bindings.glsl"
layout(local_size_x = 8, local_size_y = 8) in;
layout(rg32f, binding = BITMASK_IMAGE_MICRORECTS_HSM0) uniform readonly image2D u_hsm0;
layout(rgba32f, binding = BITMASK_IMAGE_MICRORECTS_EXTENT_IN) uniform readonly image2D u_extent_in;
layout(r32f, binding = BITMASK_IMAGE_MICRORECTS_DEPTH_IN) uniform readonly image2D u_depth_in;
layout(rgba32f, binding = BITMASK_IMAGE_MICRORECTS_EXTENT_OUT) uniform writeonly image2D u_extent_out;
layout(r32f, binding = BITMASK_IMAGE_MICRORECTS_DEPTH_OUT) uniform writeonly image2D u_depth_out;
uniform int u_from_hsm;
uniform float u_empty;  // the distance of texels without casters

const vec4 kNone = vec4(1e9, 1e9, -1e9, -1e9);
ivec2 g_size;  // level k's size

bool inside(ivec2 q) { return all(greaterThanEqual(q, ivec2(0))) && all(lessThan(q, g_size)); }
float depthAt(ivec2 q) { return inside(q) ? imageLoad(u_depth_in, q).r : u_empty; }
vec4 extentAt(ivec2 q) { return inside(q) ? imageLoad(u_extent_in, q) : kNone; }
vec4 unite(vec4 a, vec4 b) { return vec4(min(a.xy, b.xy), max(a.zw, b.zw)); }
bool contains(vec4 outer, vec4 e) {
    return e.x > e.z || (all(lessThanEqual(outer.xy, e.xy)) && all(greaterThanEqual(outer.zw, e.zw)));
}
// |a - b|, infinite when either has no caster.
float gap(float a, float b) { return a >= u_empty || b >= u_empty ? 1e30 : abs(a - b); }
// Whether the odd texel Q between even texels LO and HI merges with LO (pass 1 of LO).
bool mergesDown(ivec2 q, ivec2 lo, ivec2 hi) {
    float z = depthAt(q);
    return gap(z, depthAt(lo)) <= gap(z, depthAt(hi));
}

struct Merged {
    vec4 extent;
    float depth;
};
void take(inout Merged m, ivec2 q) {
    if (!inside(q)) return;
    m.extent = unite(m.extent, extentAt(q));
    m.depth = min(m.depth, depthAt(q));
}
// Pass 1 of the microrect with reference point A: A, B and D by depth, E by containment.
Merged firstPass(ivec2 a) {
    Merged m = Merged(extentAt(a), depthAt(a));
    if (mergesDown(a + ivec2(1, 0), a, a + ivec2(2, 0))) take(m, a + ivec2(1, 0));
    if (mergesDown(a + ivec2(0, 1), a, a + ivec2(0, 2))) take(m, a + ivec2(0, 1));
    if (inside(a + 1) && contains(m.extent, extentAt(a + 1))) take(m, a + 1);
    return m;
}

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, imageSize(u_extent_out)))) return;
    if (u_from_hsm == 1) {
        float z = imageLoad(u_hsm0, p).r;
        imageStore(u_extent_out, p, z < u_empty ? vec4(p, p) : kNone);
        imageStore(u_depth_out, p, vec4(z));
        return;
    }
    g_size = imageSize(u_extent_in);
    ivec2 a = 2 * p;
    Merged m = firstPass(a);
    ivec2 left = a - ivec2(1, 0), down = a - ivec2(0, 1);
    if (left.x >= 0 && !mergesDown(left, left - ivec2(1, 0), a)) take(m, left);
    if (down.y >= 0 && !mergesDown(down, down - ivec2(0, 1), a)) take(m, down);
    if (a.x > 0 && a.y > 0) {
        ivec2 diagonal = a - 1;
        if (!contains(firstPass(a - 2).extent, extentAt(diagonal))) take(m, diagonal);
    }
    imageStore(u_extent_out, p, m.extent);
    imageStore(u_depth_out, p, vec4(m.depth));
}
