#version 450 core
// `bitmask` microrects' caster sums (`rect_fit` coverage), the rows pass of a summed-area table
// (passes::SummedAreaTable, unsigned; its columns pass sums down): the level-0 texels that hold a
// caster, with their x and y summed too, so that microrect_fit.comp counts the casters inside
// any rectangle, and finds their mean position, with four reads. One invocation per map row y
// writes its running sums into row y + 1 of the (N + 1) x (N + 1) table; row 0 and column 0 are
// zero.
#include "techniques/bitmask/bindings.glsl"
layout(local_size_x = 64) in;
layout(rg32f, binding = BITMASK_IMAGE_CASTER_SUMS_MAP) uniform readonly image2D u_map;
// (casters, sum of x, sum of y, 0) over texels [0, x) x [0, y) at (x, y); wraps at 2^32
layout(rgba32ui, binding = BITMASK_IMAGE_CASTER_SUMS) uniform writeonly uimage2D u_sums;
uniform float u_empty;  // the distance of texels without casters

void main() {
    int y = int(gl_GlobalInvocationID.x);
    int size = imageSize(u_map).x;
    if (y >= size) return;
    uvec4 sum = uvec4(0u);
    imageStore(u_sums, ivec2(0, y + 1), sum);
    for (int x = 0; x < size; ++x) {
        if (imageLoad(u_map, ivec2(x, y)).r < u_empty) sum += uvec4(1u, uint(x), uint(y), 0u);
        imageStore(u_sums, ivec2(x + 1, y + 1), sum);
    }
    if (y == 0)  // row 0 of the table
        for (int x = 0; x <= size; ++x) imageStore(u_sums, ivec2(x, 0), uvec4(0u));
}
