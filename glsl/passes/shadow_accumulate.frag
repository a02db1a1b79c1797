#version 450 core
// Adds sum_k weight_k * lit_k over a batch of light-sample shadow maps to the bound target
// (additive blending). Normal-offset and constant bias; PCF over a PCF x PCF texel kernel.
#include "common/sample_view.glsl"

in vec2 v_uv;
layout(binding = 0) uniform sampler2D u_position;
layout(binding = 1) uniform sampler2D u_normal;
layout(binding = 2) uniform sampler2DArrayShadow u_maps;

uniform int u_view_base;
uniform int u_count;
uniform int u_pcf;              // kernel width in texels (1 = a single hard test)
uniform float u_normal_offset;  // in texels at the receiver's distance
uniform float u_depth_bias;     // in linear depth units

layout(location = 0) out vec4 o_visibility;

float lookup(int layer, SampleView v, vec3 p, vec3 n) {
    // No horizon test here: a sample below the receiver's horizon is hidden by the receiver's
    // own surface where that surface casts shadows (the map shows it), and the irradiance
    // already leaves that part of the light out, so visibility must not count it twice.
    float dist = dot(p - v.origin.xyz, v.forward.xyz);
    vec3 q = p + n * (u_normal_offset * v.params.y * max(dist, 0.0));
    vec4 clip = v.view_proj * vec4(q, 1.0);
    if (clip.w <= 0.0) return 1.0;
    vec2 uv = clip.xy / clip.w * 0.5 + 0.5;
    // Outside every caster's projection, nothing can block this sample.
    if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0)))) return 1.0;
    float d = sampleLinearDepth(v, q) - u_depth_bias;
    if (d <= 0.0) return 1.0;  // nearer to the light than every caster
    d = min(d, 1.0 - 1e-6);     // beyond the far plane: compare against the farthest caster
    if (u_pcf <= 1) return texture(u_maps, vec4(uv, float(layer), d));
    vec2 texel = 1.0 / vec2(textureSize(u_maps, 0).xy);
    float sum = 0.0;
    float start = -0.5 * float(u_pcf - 1);
    for (int y = 0; y < u_pcf; ++y)
        for (int x = 0; x < u_pcf; ++x)
            sum += texture(u_maps, vec4(uv + (vec2(x, y) + start) * texel, float(layer), d));
    return sum / float(u_pcf * u_pcf);
}

void main() {
    ivec2 pix = ivec2(gl_FragCoord.xy);
    vec4 pos = texelFetch(u_position, pix, 0);
    if (pos.w == 0.0) discard;
    vec3 n = normalize(texelFetch(u_normal, pix, 0).xyz);
    float sum = 0.0;
    for (int i = 0; i < u_count; ++i) {
        SampleView v = u_views[u_view_base + i];
        sum += v.origin.w * lookup(i, v, pos.xyz, n);
    }
    o_visibility = vec4(sum, 0.0, 0.0, 0.0);
}
