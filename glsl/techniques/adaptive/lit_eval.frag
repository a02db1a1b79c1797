#version 450 core
// `adaptive`: the light's visibility from its maps' shadow bits (lit_bits.frag): adds
// sum_k w_k lit_k, and the beauty sums, as passes/shadow_accumulate.frag does from the maps
// themselves (hard tests), with no map left to read: each view costs a bit and a few flops.
// Each screen tile weights the views of its own leaves (the cells refined there), and loops
// over those alone. SETTLE 1: only the pixels lit by every view (and those with no surface),
// drawn first so that SETTLE 0 runs on the others alone (lit_bits.cpp, passes::drawInTurn).
#include "common/bindings.glsl"
#include "common/caster_flags.glsl"
#include "common/geometric_normal.glsl"
#include "techniques/adaptive/bindings.glsl"

#ifndef SETTLE
#define SETTLE 0
#endif

layout(std140, binding = BINDING_SAMPLE_LOOKUPS) uniform SampleLookups {
    vec4 u_lookups[3 * MAX_SAMPLE_LOOKUPS];
};
layout(std430, binding = ADAPTIVE_BINDING_LIT_BITS) readonly buffer LitBits {
    uint u_bits[];  // plane-major: word w of pixel p at w * u_pixels + p; set: shadowed
};

layout(std430, binding = ADAPTIVE_BINDING_LIT_TILE_SETS) readonly buffer TileBlocks {
    uint u_tile_blocks[];  // per screen tile: its weights' block in u_blocks
};
layout(std430, binding = ADAPTIVE_BINDING_LIT_WEIGHTS) readonly buffer Blocks {
    // A block: n, the bits of sum_k w_k (in view order, in float), then n pairs of a view k and
    // the bits of w_k, ascending in k, for the views of nonzero weight in the tile.
    uint u_blocks[];
};

in vec2 v_uv;
layout(binding = UNIT_ACCUMULATE_POSITION) uniform sampler2D u_position;
layout(binding = UNIT_ACCUMULATE_NORMAL) uniform sampler2D u_normal;
layout(binding = UNIT_ACCUMULATE_ID) uniform isampler2D u_id;

uniform int u_count;   // the light's views
uniform int u_width;   // G-buffer width
uniform int u_pixels;  // G-buffer pixels (one bit plane)
uniform int u_tile_side;     // screen tiles' side in pixels
uniform int u_tile_columns;  // screen tiles per row
#include "common/light_frame.glsl"

layout(location = 0) out vec4 o_visibility;

void main() {
    ivec2 pix = ivec2(gl_FragCoord.xy);
    vec4 pos = texelFetch(u_position, pix, 0);
#if SETTLE
    if (pos.w == 0.0) {
        o_visibility = vec4(0.0);  // no surface: blending adds nothing
        return;
    }
#endif
    bool casts = objectCasts(texelFetch(u_id, pix, 0).r);
    int at = pix.y * u_width + pix.x;
    ivec2 tile = pix / u_tile_side;
    int block = int(u_tile_blocks[tile.y * u_tile_columns + tile.x]);
#if SETTLE
    // A pixel of an object that casts no shadow, lit by every map (most of an image: skip_lit
    // tests only the pixels a caster may shadow, the others' bits stay clear): every view is
    // lit, so the sums below are sum_k w_k and a contribution share of exactly 1: the host's
    // sum of the tile's weights (the same floats), without the per-view geometry.
    if (!casts) {
        uint any_shadowed = 0u;
        for (int base = 0; base < u_count; base += 32)
            any_shadowed |= u_bits[(base >> 5) * u_pixels + at];
        if (any_shadowed == 0u) {
            o_visibility = vec4(uintBitsToFloat(u_blocks[block + 1]), 1.0, 1.0, 1.0);
            return;
        }
    }
    discard;  // for the full evaluation, drawn next
#else
    // Drawn after SETTLE 1 (passes::drawInTurn): every pixel here has a surface and needs
    // the full sums, so no early out and no discard (either costs the whole block on llvmpipe).
    vec3 n = normalize(texelFetch(u_normal, pix, 0).xyz);
    vec3 q0 = inLightAxes(pos.xyz);
    vec3 nl = inLightAxes(n);
    vec3 gfl = inLightAxes(geometricNormal(pix));
    int views = int(u_blocks[block]);
    float sum = 0.0, weighted = 0.0, weights = 0.0;
    int word = -1;
    uint shadowed = 0u;
    for (int j = 0; j < views; ++j) {
        int k = int(u_blocks[block + 2 + 2 * j]);
        float w = uintBitsToFloat(u_blocks[block + 3 + 2 * j]);
        if (k >> 5 != word) {
            word = k >> 5;
            shadowed = u_bits[word * u_pixels + at];
        }
        // As shadow_accumulate.frag: a sample below a caster's tangent plane is hidden.
        vec3 d = u_lookups[3 * k].xyz - q0;
        bool hidden = ((shadowed >> uint(k & 31)) & 1u) != 0u || (casts && dot(gfl, d) <= 0.0);
        float lit = hidden ? 0.0 : 1.0;
        float d2 = dot(d, d);
        float c = max(dot(nl, d), 0.0) * max(-d.z, 0.0) / max(d2 * d2, 1e-30);
        sum += w * lit;
        weighted += w * c * lit;
        weights += w * c;
    }
    o_visibility = vec4(sum, weighted, weights, 1.0);  // a: the light was sampled
#endif
}
