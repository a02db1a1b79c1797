#version 450 core
// `css` basis images from a linear-depth shadow map: for order M, layers 0..P-1 hold the CSM
// basis (cos c_k z, sin c_k z) for two k each, layers P..2P-1 the CSM-Z basis (z cos c_k z,
// z sin c_k z), layer 2P holds z and the caster coverage (1 where a caster was rasterised)
// (P = ceil(M / 2), c_k = pi (2k - 1)); with MIDDLE its third channel holds zm - z. With MIDDLE
// the CSM-Z basis is zm cos c_k z, zm sin c_k z, zm the depth u_middle_at of the way from the
// texel's nearest to its farthest caster surface, so the blocker search averages depths inside
// a caster (at 0.5 a ball's silhouette) rather than of its side facing the light (the paper's
// z, which makes the kernel of a round caster too wide). Every value is stored minus its value
// for an empty texel (z = 1: cos = -1, sin = 0), so the uncovered part of the
// map and everything outside it is exactly 0: mipmaps use a zero border and summed-area tables
// grow only with the area that casters cover (FP32 precision).
// SAT_ROWS 0: one invocation per texel writes the basis images (for mipmaps). SAT_ROWS 1: one
// invocation per row writes the running sums of the row's basis values into row y + 1 of the
// (N + 1)^2 summed-area table (row 0 and column 0 zero), as passes/sat_rows.comp would from the
// images, which are never stored: passes/sat_columns.comp then sums down the columns.
#include "techniques/css/bindings.glsl"
#include "techniques/css/basis_layout.glsl"

#ifndef SAT_ROWS
#define SAT_ROWS 0
#endif

#if SAT_ROWS
layout(local_size_x = 64) in;
#else
layout(local_size_x = 8, local_size_y = 8) in;
#endif

layout(binding = CSS_UNIT_BASIS_DEPTH) uniform sampler2D u_depth;
#if MIDDLE
layout(binding = CSS_UNIT_BASIS_FAR) uniform sampler2D u_far;  // 0 where no caster
uniform float u_middle_at;
#endif
// The basis images (N^2), or with SAT_ROWS the summed-area table ((N + 1)^2)
layout(rgba32f, binding = CSS_IMAGE_BASIS) uniform writeonly image2DArray u_basis;

// The basis values of texel P, layer by layer (the layout above).
void basisAt(ivec2 p, out vec4 layers[CSS_LAYERS]) {
    float z = texelFetch(u_depth, p, 0).r;
#if MIDDLE
    float z_far = texelFetch(u_far, p, 0).r;
    float zm = z < 1.0 && z_far > z ? z + u_middle_at * (z_far - z) : z;
#else
    float zm = z;
#endif
    for (int i = 0; i < CSS_PAIRS; ++i) {
        float c1 = cssCoefficient(2 * i + 1), c2 = cssCoefficient(2 * i + 2);
        vec4 b = vec4(cos(c1 * z) + 1.0, sin(c1 * z), cos(c2 * z) + 1.0, sin(c2 * z));
        if (2 * i + 2 > ORDER) b.zw = vec2(0.0);  // an odd order leaves the last half empty
        layers[i] = b;
        // z cos(c z) at z = 1 is -1 as well: the same centring (zm is 1 there too).
        vec4 bz = vec4(zm * cos(c1 * z) + 1.0, zm * sin(c1 * z), zm * cos(c2 * z) + 1.0,
                       zm * sin(c2 * z));
        if (2 * i + 2 > ORDER) bz.zw = vec2(0.0);
        layers[CSS_PAIRS + i] = bz;
    }
    // z, and whether a caster covers the texel (real depths stay below 1 - m, csm_maps.h).
    layers[2 * CSS_PAIRS] = vec4(z - 1.0, z < 1.0 ? 1.0 : 0.0, zm - z, 0.0);
}

void main() {
    int n = textureSize(u_depth, 0).x;
    vec4 layers[CSS_LAYERS];
#if SAT_ROWS
    int y = int(gl_GlobalInvocationID.x);
    if (y >= n) return;
    vec4 sums[CSS_LAYERS];
    for (int l = 0; l < CSS_LAYERS; ++l) {
        sums[l] = vec4(0.0);
        imageStore(u_basis, ivec3(0, y + 1, l), sums[l]);
        if (y == 0)  // row 0 of the table
            for (int x = 0; x <= n; ++x) imageStore(u_basis, ivec3(x, 0, l), vec4(0.0));
    }
    for (int x = 0; x < n; ++x) {
        basisAt(ivec2(x, y), layers);
        for (int l = 0; l < CSS_LAYERS; ++l) {
            sums[l] += layers[l];
            imageStore(u_basis, ivec3(x + 1, y + 1, l), sums[l]);
        }
    }
#else
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, ivec2(n)))) return;
    basisAt(p, layers);
    for (int l = 0; l < CSS_LAYERS; ++l) imageStore(u_basis, ivec3(p, l), layers[l]);
#endif
}
