#version 450 core
// `bitmask` microrects' caster sums (`rect_fit` coverage): a summed-area table of the level-0
// texels that hold a caster, with their x and y summed too, so that microrect_fit.comp counts
// the casters inside any rectangle, and finds their mean position, with four reads. Two
// dispatches: u_pass 0 sums each row along x from the map, u_pass 1 each column along y in place.
// The sums wrap at 2^32; a difference of four of them is exact while the rectangle's sums fit.
#include "techniques/bitmask/bindings.glsl"
layout(local_size_x = 64) in;
layout(rg32f, binding = BITMASK_IMAGE_CASTER_SUMS_MAP) uniform readonly image2D u_map;
// (casters, sum of x, sum of y, 0) over [0, x] x [0, y]
layout(rgba32ui, binding = BITMASK_IMAGE_CASTER_SUMS) uniform uimage2D u_sums;
uniform int u_pass;
uniform float u_empty;  // the distance of texels without casters

void main() {
    int i = int(gl_GlobalInvocationID.x);
    int size = imageSize(u_sums).x;
    if (i >= size) return;
    uvec4 sum = uvec4(0u);
    if (u_pass == 0) {
        for (int x = 0; x < size; ++x) {
            if (imageLoad(u_map, ivec2(x, i)).r < u_empty) sum += uvec4(1u, uint(x), uint(i), 0u);
            imageStore(u_sums, ivec2(x, i), sum);
        }
    } else {
        for (int y = 0; y < size; ++y) {
            sum += imageLoad(u_sums, ivec2(i, y));
            imageStore(u_sums, ivec2(i, y), sum);
        }
    }
}
