#version 450 core
// `adaptive`: the hard tests of a batch of light-sample maps at every G-buffer pixel, one bit per
// view (set: shadowed) in a bit buffer kept for the whole light, so that each map is tested once
// and dropped: the cells' comparisons read the bits back and lit_eval.frag weights them. Only
// pixels whose stencil lit_region.frag set are shaded, and of a view only the screen tiles its
// cells are refined in (the others weigh it 0): the others' bits stay clear.
#include "common/sample_view.glsl"
#include "techniques/adaptive/bindings.glsl"

// The stencil test (lit_region.frag's) must come before the shader, which writes a buffer.
layout(early_fragment_tests) in;

layout(std140, binding = BINDING_SAMPLE_LOOKUPS) uniform SampleLookups {
    vec4 u_lookups[3 * MAX_SAMPLE_LOOKUPS];
};
layout(std430, binding = ADAPTIVE_BINDING_LIT_BITS) buffer LitBits {
    uint u_bits[];  // plane-major: word w of pixel p at w * u_pixels + p
};

layout(std430, binding = ADAPTIVE_BINDING_LIT_TILE_VIEWS) readonly buffer TileViews {
    uint u_tile_views[];  // tile-major: word w of tile t at t * u_planes + w; set: tested
};

layout(binding = ADAPTIVE_UNIT_COMPARE_POSITION) uniform sampler2D u_position;
layout(binding = ADAPTIVE_UNIT_COMPARE_NORMAL) uniform sampler2D u_normal;
layout(binding = ADAPTIVE_UNIT_COMPARE_ID) uniform isampler2D u_id;
// Raw linear depths (no compare sampler); layer i holds view u_view_base + i
layout(binding = ADAPTIVE_UNIT_COMPARE_MAPS) uniform sampler2DArray u_maps;

uniform int u_view_base;        // the batch's first view
uniform int u_count;            // views in the batch, at most 32
uniform int u_width;            // G-buffer width
uniform int u_pixels;           // G-buffer pixels (one bit plane)
uniform int u_planes;           // words per pixel (and per tile of u_tile_views)
uniform int u_tile_side;        // screen tiles' side in pixels
uniform int u_tile_columns;     // screen tiles per row
uniform float u_normal_offset;  // as in the shadow test: texels at the receiver's distance
uniform float u_depth_bias;
#include "common/light_frame.glsl"
#include "common/caster_flags.glsl"
#include "common/receiver_point.glsl"

// Whether layer I (view u_view_base + I) lights receiver Q (light frame), as the shadow test's
// hard test (pcf 1) decides.
bool lit(int i, vec3 q) {
    int k = u_view_base + i;
    vec4 light_origin = u_lookups[3 * k];
    vec4 frustum = u_lookups[3 * k + 1];
    float z = q.z - light_origin.z;
    if (z <= light_origin.w) return true;
    vec2 uv = ((q.xy - light_origin.xy) / z - frustum.xy) * frustum.zw;
    if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0)))) return true;
    float d = min((z - light_origin.w) * u_lookups[3 * k + 2].x - u_depth_bias, 1.0 - 1e-6);
    return d <= texture(u_maps, vec3(uv, float(i))).r;
}

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    // The batch's views this pixel's tile tests, at their bits' places.
    int shift = u_view_base & 31, word = u_view_base >> 5;
    ivec2 tile = pixel / u_tile_side;
    int at_tile = (tile.y * u_tile_columns + tile.x) * u_planes + word;
    uvec2 tested = uvec2(u_tile_views[at_tile], 0u);
    if (word + 1 < u_planes) tested.y = u_tile_views[at_tile + 1];
    uvec2 batch = uvec2(u_count + shift >= 32 ? ~0u : (1u << uint(u_count + shift)) - 1u,
                        u_count + shift > 32 ? (1u << uint(u_count + shift - 32)) - 1u : 0u);
    batch.x &= ~((1u << uint(shift)) - 1u);
    if (all(equal(tested & batch, uvec2(0u)))) return;
    vec4 pos = texelFetch(u_position, pixel, 0);
    if (pos.w == 0.0) return;  // no receiver: its bits stay clear, lit by every map
    vec3 n = normalize(texelFetch(u_normal, pixel, 0).xyz);
    // The evaluation's normal offset: from the light's first view (all are nearly the same).
    bool casts = objectCasts(texelFetch(u_id, pixel, 0).r);
    vec3 p = receiverTestPoint(pos.xyz, n, casts, u_normal_offset, u_views[0].params.y);
    vec3 q = inLightAxes(p);
    uvec2 bits = uvec2(0u);  // the batch spans at most two words
    for (int i = 0; i < u_count; ++i) {
        uint bit = 1u << uint((shift + i) & 31);
        int w = (shift + i) >> 5;
        if ((tested[w] & bit) != 0u && !lit(i, q)) bits[w] |= bit;
    }
    int at = word * u_pixels + pixel.y * u_width + pixel.x;
    if (bits.x != 0u) u_bits[at] |= bits.x;
    if (bits.y != 0u) u_bits[at + u_pixels] |= bits.y;
}
