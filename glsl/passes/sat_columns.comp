#version 450 core
// Summed-area table, pass 2 of 2: one invocation per column and layer adds the row sums of
// sat_rows.comp (or a caller's own rows pass) down its column, in place.
#include "common/bindings.glsl"
#include "passes/sat_format.glsl"
layout(local_size_x = 64) in;
layout(SAT_LAYOUT, binding = IMAGE_SAT_COLUMNS_TABLE) uniform SAT_IMAGE u_table;

void main() {
    ivec3 size = imageSize(u_table);
    int x = int(gl_GlobalInvocationID.x), layer = int(gl_GlobalInvocationID.y);
    if (x >= size.x || layer >= size.z) return;
    SAT_TEXEL sum = SAT_TEXEL(0);
    for (int y = 1; y < size.y; ++y) {
        sum += imageLoad(u_table, ivec3(x, y, layer));
        imageStore(u_table, ivec3(x, y, layer), sum);
    }
}
