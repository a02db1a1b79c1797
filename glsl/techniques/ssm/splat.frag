#version 450 core
// `ssm` splat: the share of the light one micro-patch hides from the receiver seen through this
// soft-shadow-map texel. The patch is back-projected from the receiver onto the light and the
// covered area is the product of two interval intersections (Atty et al. 3.4, 4.2); the host
// sums the patches with additive blending, once per receiver layer.
#include "techniques/ssm/bindings.glsl"
// Linear receiver depth, 1 = none
layout(binding = SSM_UNIT_SPLAT_RECEIVER) uniform sampler2DArray u_receiver;
uniform int u_layer;                                     // the receiver layer splatted into
uniform vec2 u_light_half;
uniform vec2 u_ssm_lo;
uniform vec2 u_ssm_texel;      // one soft-shadow-map texel at distance 1
uniform float u_receiver_near;
uniform float u_receiver_range;
uniform float u_depth_bias;    // a patch must be this fraction of z_R nearer than the receiver

layout(binding = SSM_UNIT_SPLAT_LAYER_IDS) uniform isampler2DArray u_layer_ids;
uniform int u_layer_count;

flat in vec4 v_patch;
flat in float v_depth;
flat in int v_object;
flat in int v_separated;

layout(location = 0) out vec4 o_occlusion;

void main() {
    ivec2 texel = ivec2(gl_FragCoord.xy);
    float dr = texelFetch(u_receiver, ivec3(texel, u_layer), 0).r;
    if (dr >= 1.0) discard;
    float zr = u_receiver_near + dr * u_receiver_range;
    if (zr - v_depth <= u_depth_bias * zr) discard;
    // A patch does not shadow its own object's surface unless it lies apart from it (splat.vert).
    if (u_layer_count > 1 && v_separated == 0 &&
        texelFetch(u_layer_ids, ivec3(texel, u_layer), 0).r == v_object)
        discard;
    vec2 p = (u_ssm_lo + (vec2(texel) + 0.5) * u_ssm_texel) * zr;
    // From p through the patch onto the light plane (distance 0), in light units [0, 1].
    float s = zr / (zr - v_depth);
    vec4 onto = p.xyxy + (v_patch - p.xyxy) * s;
    vec4 unit = clamp((onto + u_light_half.xyxy) / (2.0 * u_light_half.xyxy), 0.0, 1.0);
    vec2 covered = unit.zw - unit.xy;
    o_occlusion = vec4(covered.x * covered.y, 0.0, 0.0, 0.0);
}
