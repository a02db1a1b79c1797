#version 450 core
// `adaptive`: two triangles over each screen tile of a list (six vertices a tile, no attributes),
// so that lit_bits.frag runs only in the tiles a batch of views is tested in.
#include "techniques/adaptive/bindings.glsl"

layout(std430, binding = ADAPTIVE_BINDING_LIT_TILE_LIST) readonly buffer TileList {
    uint u_tile_list[];  // the tiles to cover
};

uniform int u_tile_side;     // screen tiles' side in pixels
uniform int u_tile_columns;  // screen tiles per row
uniform vec2 u_viewport;     // the G-buffer's size in pixels

const vec2 kCorners[6] =
    vec2[](vec2(0.0), vec2(1.0, 0.0), vec2(1.0), vec2(0.0), vec2(1.0), vec2(0.0, 1.0));

void main() {
    int tile = int(u_tile_list[gl_VertexID / 6]);
    vec2 at = vec2(tile % u_tile_columns, tile / u_tile_columns) + kCorners[gl_VertexID % 6];
    vec2 pixels = min(at * float(u_tile_side), u_viewport);
    gl_Position = vec4(pixels / u_viewport * 2.0 - 1.0, 0.0, 1.0);
}
