#version 450 core
// `adaptive`: compares two light-sample shadow maps over a G-buffer (Schwärzler 2009, eq. 3
// or 7) at every u_stride-th G-buffer pixel in x and y. Agreeing pixels are discarded, so an
// occlusion query counts the disagreeing ones. Mode 1 counts instead the pixels that any of
// four views shadows (the shadow region the error metric divides by).
#include "techniques/adaptive/bindings.glsl"
#include "common/sample_view.glsl"

layout(std140, binding = BINDING_SAMPLE_LOOKUPS) uniform SampleLookups {
    vec4 u_lookups[3 * MAX_SAMPLE_LOOKUPS];
};

// Per screen tile and comparison, the disagreeing pixels (the local metric; u_tile_size 0: off).
layout(std430, binding = ADAPTIVE_BINDING_COMPARE_TILE_COUNTS) buffer TileCounts {
    uint u_tile_counts[];
};

in vec2 v_uv;
layout(binding = ADAPTIVE_UNIT_COMPARE_POSITION) uniform sampler2D u_position;
layout(binding = ADAPTIVE_UNIT_COMPARE_NORMAL) uniform sampler2D u_normal;
layout(binding = ADAPTIVE_UNIT_COMPARE_ID) uniform isampler2D u_id;
// Raw linear depths (no compare sampler)
layout(binding = ADAPTIVE_UNIT_COMPARE_MAPS) uniform sampler2DArray u_maps;

uniform int u_view_a;     // the two views (= layers) compared
uniform int u_view_b;
uniform int u_mode;       // 0: a and b disagree; 1: any of a, b, c, d shadows (hard tests)
uniform int u_view_c;     // mode 1's other two views
uniform int u_view_d;
uniform float u_gamma;    // largest depth difference still considered equal
uniform int u_tests;           // 1: compare hard-shadow test results instead of depths
uniform float u_normal_offset;  // as in the shadow test: texels at the receiver's distance
uniform float u_depth_bias;
#include "common/light_frame.glsl"
#include "common/caster_flags.glsl"
#include "common/receiver_point.glsl"
uniform int u_relative;   // 0: |d_a - d_b| < gamma (eq. 3); 1: |1 - d_a / d_b| < gamma (eq. 7)
uniform int u_tile_size;  // pixels per tile side, 0: no tile counts
uniform int u_tiles_x;
uniform int u_tile_slot;  // this comparison's first counter: slot * tile count
uniform int u_level;      // quadtree depth of the comparison, written (+1) to the diagnostic
uniform int u_stride;     // G-buffer pixels per comparison pixel along x and y

layout(location = 0) out vec4 o_level;  // max-blended: the deepest disagreement here, + 1

// The stored caster depth that view K sees along the ray to receiver Q (light frame); 1 (the
// far plane) where no caster projects.
float storedDepth(int k, vec3 q) {
    vec4 light_origin = u_lookups[3 * k];
    vec4 frustum = u_lookups[3 * k + 1];
    float z = q.z - light_origin.z;
    if (z <= light_origin.w) return 1.0;
    vec2 uv = ((q.xy - light_origin.xy) / z - frustum.xy) * frustum.zw;
    if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0)))) return 1.0;
    return texture(u_maps, vec3(uv, float(k))).r;
}

// Whether view K's map lights receiver Q (light frame), as the evaluation's hard test decides.
bool lit(int k, vec3 q) {
    vec4 light_origin = u_lookups[3 * k];
    vec4 frustum = u_lookups[3 * k + 1];
    float z = q.z - light_origin.z;
    if (z <= light_origin.w) return true;
    vec2 uv = ((q.xy - light_origin.xy) / z - frustum.xy) * frustum.zw;
    if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0)))) return true;
    float d = min((z - light_origin.w) * u_lookups[3 * k + 2].x - u_depth_bias, 1.0 - 1e-6);
    return d <= texture(u_maps, vec3(uv, float(k))).r;
}

void main() {
    // The centre pixel of this comparison pixel's u_stride x u_stride block.
    ivec2 pixel = min(ivec2(gl_FragCoord.xy) * u_stride + u_stride / 2,
                      textureSize(u_position, 0) - 1);
    vec4 pos = texelFetch(u_position, pixel, 0);
    if (pos.w == 0.0) discard;
    vec3 q = vec3(dot(pos.xyz, u_light_right), dot(pos.xyz, u_light_up),
                  dot(pos.xyz, u_light_forward));
    if (u_tests != 0 || u_mode == 1) {
        vec3 n = normalize(texelFetch(u_normal, pixel, 0).xyz);
        bool casts = objectCasts(texelFetch(u_id, pixel, 0).r);
        vec3 p = receiverTestPoint(pos.xyz, n, casts, u_normal_offset, u_views[u_view_a].params.y);
        vec3 qo = vec3(dot(p, u_light_right), dot(p, u_light_up), dot(p, u_light_forward));
        if (u_mode == 1) {
            if (lit(u_view_a, qo) && lit(u_view_b, qo) && lit(u_view_c, qo) && lit(u_view_d, qo))
                discard;
            o_level = vec4(0.0);  // no refinement level: max blending leaves the diagnostic
            return;
        }
        if (lit(u_view_a, qo) == lit(u_view_b, qo)) discard;
    } else {
        float da = storedDepth(u_view_a, q);
        float db = storedDepth(u_view_b, q);
        float diff = u_relative != 0 ? abs(1.0 - da / max(db, 1e-6)) : abs(da - db);
        if (diff < u_gamma) discard;
    }
    if (u_tile_size > 0) {
        ivec2 tile = pixel / u_tile_size;
        atomicAdd(u_tile_counts[u_tile_slot + tile.y * u_tiles_x + tile.x], 1u);
    }
    o_level = vec4(float(u_level + 1), 0.0, 0.0, 0.0);
}
