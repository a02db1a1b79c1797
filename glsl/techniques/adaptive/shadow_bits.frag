#version 450 core
// `adaptive`: which of up to 128 light-sample maps shadow each u_stride-th G-buffer pixel (hard
// tests, as the evaluation's), one bit per map, so that the CPU compares every pair of a level's
// cells from one pass (each corner map read once, however many cells share it).
#include "techniques/adaptive/bindings.glsl"
#include "common/sample_view.glsl"

layout(std140, binding = BINDING_SAMPLE_LOOKUPS) uniform SampleLookups {
    vec4 u_lookups[3 * MAX_SAMPLE_LOOKUPS];
};

in vec2 v_uv;
layout(binding = ADAPTIVE_UNIT_COMPARE_POSITION) uniform sampler2D u_position;
layout(binding = ADAPTIVE_UNIT_COMPARE_NORMAL) uniform sampler2D u_normal;
layout(binding = ADAPTIVE_UNIT_COMPARE_ID) uniform isampler2D u_id;
// Raw linear depths (no compare sampler)
layout(binding = ADAPTIVE_UNIT_COMPARE_MAPS) uniform sampler2DArray u_maps;

uniform int u_count;      // maps tested, at most 128
uniform int u_list[128];  // their views (= layers); bit i of the output is u_list[i]'s
uniform float u_normal_offset;  // as in the shadow test: texels at the receiver's distance
uniform float u_depth_bias;
uniform int u_stride;     // G-buffer pixels per output pixel along x and y
#include "common/light_frame.glsl"
#include "common/caster_flags.glsl"
#include "common/receiver_point.glsl"

layout(location = 0) out uvec4 o_shadowed;  // bit i: view u_list[i] shadows this pixel

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
    // The centre pixel of this output pixel's u_stride x u_stride block.
    ivec2 pixel = min(ivec2(gl_FragCoord.xy) * u_stride + u_stride / 2,
                      textureSize(u_position, 0) - 1);
    vec4 pos = texelFetch(u_position, pixel, 0);
    if (pos.w == 0.0) discard;  // no receiver: the cleared 0, lit by every map
    vec3 n = normalize(texelFetch(u_normal, pixel, 0).xyz);
    // The evaluation's normal offset: from the light's first view (all are nearly the same).
    bool casts = objectCasts(texelFetch(u_id, pixel, 0).r);
    vec3 p = receiverTestPoint(pos.xyz, n, casts, u_normal_offset, u_views[0].params.y);
    vec3 q = vec3(dot(p, u_light_right), dot(p, u_light_up), dot(p, u_light_forward));
    uvec4 bits = uvec4(0u);
    for (int i = 0; i < u_count; ++i)
        if (!lit(u_list[i], q)) bits[i >> 5] |= 1u << uint(i & 31);
    o_shadowed = bits;
}
