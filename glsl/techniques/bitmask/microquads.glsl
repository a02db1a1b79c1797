// `bitmask` microquads (Bitmask Soft Shadows): the centres of 2 x 2 adjacent texels of a level,
// at their HSM depths, form a quad; projected from the receiver onto the light it is two
// triangles whose masks are ANDs of three edge-table entries (the samples left of each edge).
// A quad counts when all four corners lie in front of the receiver. Needs search.glsl and
// backproject.glsl's onLight() and maskFull().
#include "techniques/bitmask/bindings.glsl"
// (offset bin, 2 * angle bin + word half)
layout(binding = BITMASK_UNIT_VISIBILITY_EDGES) uniform usampler2D u_edges;
uniform int u_edge_angles;
uniform int u_edge_offsets;

const float kTwoPi = 6.28318530718;
const float kHalfDiagonal = 0.70710678;

// The samples left of the directed edge A -> B (light coordinates in [0,1]^2), as two halves.
void edgeMask(vec2 a, vec2 b, out uvec4 lo, out uvec4 hi) {
    vec2 e = b - a;
    vec2 n = normalize(vec2(-e.y, e.x));
    float angle = atan(n.y, n.x);
    if (angle < 0.0) angle += kTwoPi;
    int ai = int(round(angle / kTwoPi * float(u_edge_angles))) % u_edge_angles;
    float d = dot(n, a - 0.5);
    float o = (d + kHalfDiagonal) / (2.0 * kHalfDiagonal) * float(u_edge_offsets - 1);
    int oi = int(clamp(round(o), 0.0, float(u_edge_offsets - 1)));
    lo = texelFetch(u_edges, ivec2(oi, 2 * ai), 0);
    hi = texelFetch(u_edges, ivec2(oi, 2 * ai + 1), 0);
}

// The samples inside triangle A, B, C (either winding), ORed into M0, M1.
void addTriangle(vec2 a, vec2 b, vec2 c, inout uvec4 m0, inout uvec4 m1) {
    float area = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
    if (abs(area) < 1e-12) return;
    if (area < 0.0) {
        vec2 t = b;
        b = c;
        c = t;
    }
    uvec4 l0, h0, l1, h1, l2, h2;
    edgeMask(a, b, l0, h0);
    edgeMask(b, c, l1, h1);
    edgeMask(c, a, l2, h2);
    m0 |= l0 & l1 & l2;
    m1 |= h0 & h1 & h2;
}

// Back-projects the microquads of LEVEL whose first corner lies in AREA for receiver P
// (biased depth PZ) into M0, M1; COUNT += those back-projected; returns whether every light
// sample is occluded then.
bool addQuads(vec3 p, float pz, vec4 area, int level, inout uvec4 m0, inout uvec4 m1,
              inout int count) {
    ivec4 r = levelRange(area, level, 2);
    vec2 t = u_texel * float(1 << level), scale = 0.5 / u_light_half;
    for (int y = r.y; y <= r.w; ++y)
        for (int x = r.x; x <= r.z; ++x) {
            vec4 z = vec4(texelFetch(u_hsm, ivec2(x, y), level).r,
                          texelFetch(u_hsm, ivec2(x + 1, y), level).r,
                          texelFetch(u_hsm, ivec2(x + 1, y + 1), level).r,
                          texelFetch(u_hsm, ivec2(x, y + 1), level).r);
            if (any(greaterThanEqual(z, vec4(pz)))) continue;
            ++count;
            vec2 c = u_win_lo + (vec2(x, y) + 0.5) * t;
            vec2 q[4] = vec2[4](c, c + vec2(t.x, 0.0), c + t, c + vec2(0.0, t.y));
            for (int i = 0; i < 4; ++i)
                q[i] = vec2(onLight(q[i].x, p.x, p.z, z[i]), onLight(q[i].y, p.y, p.z, z[i])) *
                           scale + 0.5;
            addTriangle(q[0], q[1], q[2], m0, m1);
            addTriangle(q[0], q[2], q[3], m0, m1);
        }
    return maskFull(m0, m1);
}
