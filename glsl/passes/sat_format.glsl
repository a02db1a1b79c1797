// Summed-area tables' texel type: RGBA32F (SAT_UNSIGNED 0: filtered lookups) or RGBA32UI
// (SAT_UNSIGNED 1: exact integer sums, wrapping at 2^32), for sat_rows.comp and sat_columns.comp.
#ifndef SAT_UNSIGNED
#define SAT_UNSIGNED 0
#endif
#if SAT_UNSIGNED
#define SAT_LAYOUT rgba32ui
#define SAT_IMAGE uimage2DArray
#define SAT_TEXEL uvec4
#else
#define SAT_LAYOUT rgba32f
#define SAT_IMAGE image2DArray
#define SAT_TEXEL vec4
#endif
