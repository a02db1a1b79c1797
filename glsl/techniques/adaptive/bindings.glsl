// Binding points of `adaptive`'s shaders (texture and image units, buffers) for its GLSL and
// its C++ alike: #defines and // comments only, which both preprocessors read (see
// glsl/common/bindings.glsl); the C++ includes "glsl/techniques/adaptive/bindings.glsl".
#ifndef PENUMBRA_ADAPTIVE_BINDINGS_GLSL
#define PENUMBRA_ADAPTIVE_BINDINGS_GLSL

// compare.frag
#define ADAPTIVE_UNIT_COMPARE_POSITION 0
#define ADAPTIVE_UNIT_COMPARE_NORMAL 1
#define ADAPTIVE_UNIT_COMPARE_MAPS 2  // raw linear depths, through a non-comparing sampler
#define ADAPTIVE_UNIT_COMPARE_ID 4    // G-buffer object ids (whether a receiver casts)
#define ADAPTIVE_BINDING_COMPARE_TILE_COUNTS 7  // SSBO of uint per tile and quad

// lit_bits.frag and lit_eval.frag (the units above for the G-buffer and the maps)
#define ADAPTIVE_BINDING_LIT_BITS 8  // SSBO of uint: word w of pixel p at w * pixels + p
#define ADAPTIVE_BINDING_LIT_TILE_VIEWS 9  // SSBO of uint: the views tested in each screen tile
#define ADAPTIVE_BINDING_LIT_TILE_SETS 10  // SSBO of uint: each screen tile's weights' block
#define ADAPTIVE_BINDING_LIT_WEIGHTS 11    // SSBO of uint: the blocks (TileWeights::blocks)
#define ADAPTIVE_BINDING_LIT_HORIZON_TILES 12  // SSBO of uint: horizon_tiles.frag's flags
#define ADAPTIVE_BINDING_LIT_TILE_LIST 13  // SSBO of uint: tile_quads.vert's tiles
#define ADAPTIVE_UNIT_LIT_REGION 3  // the casters' min/max distance pyramid from the light's centre

#endif
