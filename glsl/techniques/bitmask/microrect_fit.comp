#version 450 core
// `bitmask` microrects' drawn extents (`rect_fit` coverage; not in the paper): a level's bounding
// rectangles (microrects.comp), once the next level is merged from them, shrunk in place to the
// area of the level-0 caster texels inside them (whichever microrect merged them), about those
// texels' mean position and inside the rectangle, keeping its aspect. A rectangle full of
// casters stays as it is; one a silhouette cuts diagonally no longer casts its empty part at its
// nearest depth.
#include "techniques/bitmask/bindings.glsl"
layout(local_size_x = 8, local_size_y = 8) in;
// x0, y0, x1, y1 (level-0 texels, inclusive; x0 > x1: no caster): read, and written shrunk
layout(rgba32f, binding = BITMASK_IMAGE_MICRORECT_FIT_EXTENT) uniform image2D u_extent;
// caster_sums.comp's summed-area table: (casters, sum of x, sum of y) over [0, x) x [0, y)
layout(rgba32ui, binding = BITMASK_IMAGE_MICRORECT_FIT_SUMS) uniform readonly uimage2D u_sums;

// The sums over level-0 texels [0, x] x [0, y].
uvec3 sumTo(int x, int y) { return imageLoad(u_sums, ivec2(x + 1, y + 1)).xyz; }

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, imageSize(u_extent)))) return;
    vec4 e = imageLoad(u_extent, p);
    if (e.x > e.z) return;
    vec2 side = e.zw + 1.0 - e.xy;
    float area = side.x * side.y;
    // The casters in the rectangle, in wrapping arithmetic, which gives its sums where they fit
    // in 32 bits: not so for a rectangle over most of a map of 2048 or more, left as it is.
    if (area * max(e.z, e.w) >= 4.0e9) return;
    ivec4 r = ivec4(e);
    uvec3 s = sumTo(r.z, r.w) - sumTo(r.x - 1, r.w) - sumTo(r.z, r.y - 1) + sumTo(r.x - 1, r.y - 1);
    float n = float(s.x);
    if (s.x == 0u || n >= area) return;
    vec2 mean = vec2(s.yz) / n + 0.5;  // of the texels' centres
    vec2 fitted = side * sqrt(n / area);
    vec2 lo = clamp(mean - 0.5 * fitted, e.xy, e.zw + 1.0 - fitted);
    imageStore(u_extent, p, vec4(lo, lo + fitted - 1.0));
}
