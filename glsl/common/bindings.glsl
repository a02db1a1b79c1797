// Binding points of the passes (buffer bindings, texture and image units) and the sizes of the
// structs both sides lay out: the ONE source for GLSL and C++. Written in the subset both
// preprocessors read (#define, #ifndef, // comments): shaders `#include "common/bindings.glsl"`,
// C++ includes "glsl/common/bindings.glsl" (renderer/passes/bindings.h).
#ifndef PENUMBRA_COMMON_BINDINGS_GLSL
#define PENUMBRA_COMMON_BINDINGS_GLSL

// Buffers.
#define BINDING_SAMPLE_VIEWS 0    // SSBO of SampleView (shadow_maps, common/sample_view.glsl)
#define BINDING_LIGHTS 1          // SSBO of GpuLight (shade, passes/shading.glsl)
#define BINDING_SAMPLE_LOOKUPS 2  // UBO of SampleLookup (shadow tests)
#define BINDING_CASTER_FLAGS 6    // SSBO of int per object: 1 casts (common/caster_flags.glsl)
#define MAX_SAMPLE_LOOKUPS 1024   // views per light: N = 32 squared

// std430 sizes of the structs the host mirrors (static_asserts beside each C++ mirror).
#define GPU_LIGHT_SIZE 96    // GpuLight: vec4 corners[4], forward, radiance
#define SAMPLE_VIEW_SIZE 160  // SampleView: mat4 view_proj, 6 vec4

// Texture units of the shade passes (shade.frag, shade_samples.frag, msaa_classify.frag).
#define UNIT_SHADE_POSITION 0
#define UNIT_SHADE_NORMAL 1
#define UNIT_SHADE_ALBEDO 2
#define UNIT_SHADE_VISIBILITY 3  // the technique's visibility layers (passes/shading.glsl)
#define UNIT_SHADE_ID 4
#define UNIT_SHADE_SAMPLE_POSITION 5  // MSAA: one layer per sample
#define UNIT_SHADE_SAMPLE_NORMAL 6
#define UNIT_SHADE_SAMPLE_ALBEDO 7
#define UNIT_SHADE_SAMPLE_ID 8

// Texture units of the shadow-map accumulation (shadow_accumulate.frag).
#define UNIT_ACCUMULATE_POSITION 0
#define UNIT_ACCUMULATE_NORMAL 1
#define UNIT_ACCUMULATE_MAPS 2
#define UNIT_ACCUMULATE_ID 3
#define UNIT_GEOMETRIC_NORMAL 15  // the G-buffer's geometric normal (common/geometric_normal.glsl)

// The G-buffer pass's base colour texture (gbuffer.frag).
#define UNIT_BASE_TEXTURE 0

// Image units of the summed-area tables: the row pass reads the source and writes the table,
// the column pass updates the table in place.
#define IMAGE_SAT_SOURCE 0         // sat_rows.comp
#define IMAGE_SAT_TABLE 1          // sat_rows.comp
#define IMAGE_SAT_COLUMNS_TABLE 0  // sat_columns.comp

// Image units of the distance pyramid's reduction (distance_pyramid.comp).
#define IMAGE_PYRAMID_FINER 0
#define IMAGE_PYRAMID_COARSER 1

#endif
