#version 450 core
// Summed-area table, pass 1 of 2: one invocation per row and layer writes the running sums of
// that row of the N x N source into row y + 1 of the (N + 1) x (N + 1) table, whose row 0 and
// column 0 are zero (so a box sum needs no bounds test). Pass 2 (sat_columns.comp) sums down.
#include "common/bindings.glsl"
#include "passes/sat_format.glsl"
layout(local_size_x = 64) in;
layout(SAT_LAYOUT, binding = IMAGE_SAT_SOURCE) uniform readonly SAT_IMAGE u_source;
layout(SAT_LAYOUT, binding = IMAGE_SAT_TABLE) uniform writeonly SAT_IMAGE u_table;

void main() {
    ivec3 size = imageSize(u_source);
    int y = int(gl_GlobalInvocationID.x), layer = int(gl_GlobalInvocationID.y);
    if (y >= size.y || layer >= size.z) return;
    SAT_TEXEL sum = SAT_TEXEL(0);
    imageStore(u_table, ivec3(0, y + 1, layer), sum);
    for (int x = 0; x < size.x; ++x) {
        sum += imageLoad(u_source, ivec3(x, y, layer));
        imageStore(u_table, ivec3(x + 1, y + 1, layer), sum);
    }
    if (y == 0)  // row 0 of the table
        for (int x = 0; x <= size.x; ++x) imageStore(u_table, ivec3(x, 0, layer), SAT_TEXEL(0));
}
