// Binding points of `bitmask`'s shaders (texture and image units, buffers) for its GLSL and
// its C++ alike: #defines and // comments only, which both preprocessors read (see
// glsl/common/bindings.glsl); the C++ includes "glsl/techniques/bitmask/bindings.glsl".
#ifndef PENUMBRA_BITMASK_BINDINGS_GLSL
#define PENUMBRA_BITMASK_BINDINGS_GLSL

// Texture units of search.glsl (classify.frag and visibility.frag).
#define BITMASK_UNIT_SEARCH_POSITION 0
#define BITMASK_UNIT_SEARCH_NORMAL 1
#define BITMASK_UNIT_SEARCH_ID 2
#define BITMASK_UNIT_SEARCH_RECEIVES 3  // per object id: (receives, casts)
#define BITMASK_UNIT_SEARCH_HSM 4
#define BITMASK_UNIT_SEARCH_MSSM 5
// classify.frag
#define BITMASK_UNIT_CLASSIFY_BUDGET_MAP 12
// visibility.frag and backproject.glsl, microquads.glsl
#define BITMASK_UNIT_VISIBILITY_AREA 7
#define BITMASK_UNIT_VISIBILITY_LOQ 8
#define BITMASK_UNIT_VISIBILITY_RECT_EXTENT 9
#define BITMASK_UNIT_VISIBILITY_RECT_DEPTH 10
#define BITMASK_UNIT_VISIBILITY_EDGES 11
#define BITMASK_UNIT_VISIBILITY_SAMPLES 13
#define BITMASK_UNIT_VISIBILITY_FAR 14  // layers 2: the far layer's min/max pyramid
#define BITMASK_UNIT_VISIBILITY_FAR_RECT_EXTENT 6  // and its microrects
#define BITMASK_UNIT_VISIBILITY_FAR_RECT_DEPTH 16  // 15 is UNIT_GEOMETRIC_NORMAL
#define BITMASK_UNIT_VISIBILITY_NEIGHBOURS 17      // gap_fill: neighbours.comp's levels
#define BITMASK_UNIT_VISIBILITY_FAR_NEIGHBOURS 18  // and the far layer's
#define BITMASK_UNIT_VISIBILITY_OWNERS 19      // OWN_IDS: the map's owners (microrects.comp)
#define BITMASK_UNIT_VISIBILITY_FAR_OWNERS 20  // and the far layer's
#define BITMASK_BINDING_VISIBILITY_STATS 3  // SSBO of the statistics counters
#define BITMASK_BINDING_VISIBILITY_MASKS 4  // SSBO of the half-plane masks
// loq_smooth.frag
#define BITMASK_UNIT_SMOOTH_LOQ 0
#define BITMASK_UNIT_SMOOTH_NORMAL 1
// peel.frag: the front map's distances (HSM level 0); not 0, where the scene's draw binds a
// material's base colour texture (UNIT_BASE_TEXTURE)
#define BITMASK_UNIT_PEEL_FRONT 1
#define BITMASK_UNIT_PEEL_FRONT_OWNERS 2  // and its owners (IDS 1)
// Image units of mssm.comp and microrects.comp (the HSM's: passes/distance_pyramid.comp).
#define BITMASK_IMAGE_MSSM_BELOW 0  // the layer below (or the HSM level), one 2D layer
#define BITMASK_IMAGE_MSSM 1        // the layer written
#define BITMASK_IMAGE_MSSM_NEXT 2   // the layer above it, in a pair
#define BITMASK_IMAGE_MICRORECTS_HSM0 0
#define BITMASK_IMAGE_MICRORECTS_EXTENT_IN 1
#define BITMASK_IMAGE_MICRORECTS_DEPTH_IN 2
#define BITMASK_IMAGE_MICRORECTS_EXTENT_OUT 3
#define BITMASK_IMAGE_MICRORECTS_DEPTH_OUT 4
#define BITMASK_IMAGE_MICRORECTS_OWNERS_IN 5   // OWN_IDS: the level below's owners
#define BITMASK_IMAGE_MICRORECTS_OWNERS_OUT 6  // and the level's
// caster_sums.comp: the map (HSM level 0) and the table; microrect_fit.comp: a level's
// extents (read and written) and the table
#define BITMASK_IMAGE_CASTER_SUMS_MAP 0
#define BITMASK_IMAGE_CASTER_SUMS 1
#define BITMASK_IMAGE_MICRORECT_FIT_EXTENT 3
#define BITMASK_IMAGE_MICRORECT_FIT_SUMS 2
// neighbours.comp
#define BITMASK_UNIT_NEIGHBOURS_SOURCE 0
#define BITMASK_UNIT_NEIGHBOURS_OWNERS 1  // OWN_IDS
#define BITMASK_IMAGE_NEIGHBOURS_OUT 0

#endif
