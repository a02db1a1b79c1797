#version 450 core
// Adds sum_k weight_k * lit_k over a batch of light-sample shadow maps to the bound target
// (additive blending), and in g and b sum_k weight_k c_k lit_k and sum_k weight_k c_k with c_k
// the sample's unshadowed contribution cos cos / r^2, a > 0 (the shade pass's beauty weighting). Normal-offset and constant bias; PCF over a PCF x PCF texel kernel.
// Every view of a batch shares the light's frame, so the receiver is projected once into that
// frame and each view costs a few scalar operations and one depth-compare fetch. On an object
// that casts, a sample below the receiver's tangent plane counts as hidden: the object's own
// (closed) surface hides it, as `exact`'s rays find, though the normal offset lights it; the
// plane is the drawn triangle's (the geometric normal), which is the surface those rays meet.
#include "common/bindings.glsl"
#include "common/caster_flags.glsl"
#include "common/geometric_normal.glsl"
#include "common/sample_view.glsl"

// The three lookup vectors of every view (SampleView's light_origin, frustum, depth), as a
// uniform block: software rasterisers read uniform blocks far faster than storage buffers.
layout(std140, binding = BINDING_SAMPLE_LOOKUPS) uniform SampleLookups {
    vec4 u_lookups[3 * MAX_SAMPLE_LOOKUPS];
};

in vec2 v_uv;
layout(binding = UNIT_ACCUMULATE_POSITION) uniform sampler2D u_position;
layout(binding = UNIT_ACCUMULATE_NORMAL) uniform sampler2D u_normal;
layout(binding = UNIT_ACCUMULATE_MAPS) uniform sampler2DArrayShadow u_maps;
layout(binding = UNIT_ACCUMULATE_ID) uniform isampler2D u_id;

uniform int u_view_base;
uniform int u_count;
// The PCF kernel's width in texels (1 = a single hard test), compiled in (shadow_maps.cpp).
#ifndef PCF
#define PCF 1
#endif
uniform float u_normal_offset;  // in texels at the receiver's distance
uniform float u_depth_bias;     // in linear depth units
#include "common/light_frame.glsl"
#include "common/receiver_point.glsl"

layout(location = 0) out vec4 o_visibility;

// Lit fraction (0 or 1, or the PCF average) of receiver Q (in the light's frame) for the
// batch's view LAYER.
float lookup(int layer, vec3 q) {
    int k = u_view_base + layer;
    vec4 light_origin = u_lookups[3 * k];
    vec4 frustum = u_lookups[3 * k + 1];
    float z = q.z - light_origin.z;
    float near = light_origin.w;
    if (z <= near) return 1.0;  // nearer to the light than every caster
    vec2 uv = ((q.xy - light_origin.xy) / z - frustum.xy) * frustum.zw;
    // Outside every caster's projection, nothing can block this sample.
    if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0)))) return 1.0;
    float d = (z - near) * u_lookups[3 * k + 2].x - u_depth_bias;
    d = min(d, 1.0 - 1e-6);  // beyond the far plane: compare against the farthest caster
#if PCF <= 1
    return texture(u_maps, vec4(uv, float(layer), d));
#else
    vec2 texel = 1.0 / vec2(textureSize(u_maps, 0).xy);
    float sum = 0.0;
    float start = -0.5 * float(PCF - 1);
    for (int y = 0; y < PCF; ++y)
        for (int x = 0; x < PCF; ++x)
            sum += texture(u_maps, vec4(uv + (vec2(x, y) + start) * texel, float(layer), d));
    return sum / float(PCF * PCF);
#endif
}

void main() {
    ivec2 pix = ivec2(gl_FragCoord.xy);
    vec4 pos = texelFetch(u_position, pix, 0);
    if (pos.w == 0.0) discard;
    vec3 n = normalize(texelFetch(u_normal, pix, 0).xyz);
    bool casts = objectCasts(texelFetch(u_id, pix, 0).r);
    // The normal offset in texels of the batch's first view (a light's views nearly agree).
    vec3 p = receiverTestPoint(pos.xyz, n, casts, u_normal_offset, u_views[u_view_base].params.y);
    vec3 q = vec3(dot(p, u_light_right), dot(p, u_light_up), dot(p, u_light_forward));
    // The receiver itself (no offset) and its normal in the light's frame, for c_k.
    vec3 q0 = vec3(dot(pos.xyz, u_light_right), dot(pos.xyz, u_light_up),
                   dot(pos.xyz, u_light_forward));
    vec3 nl = vec3(dot(n, u_light_right), dot(n, u_light_up), dot(n, u_light_forward));
    vec3 g = geometricNormal(pix);
    vec3 gfl = vec3(dot(g, u_light_right), dot(g, u_light_up), dot(g, u_light_forward));
    float sum = 0.0, weighted = 0.0, weights = 0.0;
    for (int i = 0; i < u_count; ++i) {
        int k = u_view_base + i;
        float w = u_lookups[3 * k + 2].y;
        // d: receiver to sample; cos_r |d| = n.d, cos_l |d| = the receiver's depth beyond it.
        vec3 d = u_lookups[3 * k].xyz - q0;
        float lit = casts && dot(gfl, d) <= 0.0 ? 0.0 : lookup(i, q);
        float d2 = dot(d, d);
        float c = max(dot(nl, d), 0.0) * max(-d.z, 0.0) / max(d2 * d2, 1e-30);
        sum += w * lit;
        weighted += w * c * lit;
        weights += w * c;
    }
    o_visibility = vec4(sum, weighted, weights, 1.0);  // a: the light was sampled
}
