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
// Per receiver layer: the unit normal of its surface in the light's frame (receiver_planes.comp)
layout(binding = SSM_UNIT_SPLAT_PLANES) uniform sampler2DArray u_planes;
uniform int u_layer_count;

flat in vec4 v_patch;
flat in float v_depth;
flat in int v_object;
flat in int v_separated;

layout(location = 0) out vec4 o_occlusion;

// Whether the whole micro-patch lies above the tangent plane of the receiver P at texel T
// (receiver_planes.comp) by a margin for that plane's estimate: then the light it hides from P
// lies above P's horizon, none of it the part the visibility pass takes in closed form.
bool aboveTangentPlane(ivec2 t, vec3 p) {
    vec3 n = texelFetch(u_planes, ivec3(t, u_layer), 0).xyz;
    if (n == vec3(0.0)) return false;
    // The patch's lowest corner over the plane: each axis's nearer side.
    vec2 lo = min(n.xy * v_patch.xy, n.xy * v_patch.zw);
    float height = lo.x + lo.y + n.z * v_depth - dot(n, p);
    return height > (u_depth_bias + 2.0 * max(u_ssm_texel.x, u_ssm_texel.y)) * p.z;
}

void main() {
    ivec2 texel = ivec2(gl_FragCoord.xy);
    float dr = texelFetch(u_receiver, ivec3(texel, u_layer), 0).r;
    if (dr >= 1.0) discard;
    float zr = u_receiver_near + dr * u_receiver_range;
    if (zr - v_depth <= u_depth_bias * zr) discard;
    vec2 p = (u_ssm_lo + (vec2(texel) + 0.5) * u_ssm_texel) * zr;
    // A patch does not shadow its own object's surface unless it lies apart from it (splat.vert)
    // or wholly above that surface's tangent plane here (a head over the body it rests on).
    if (u_layer_count > 1 && v_separated == 0) {
        if (texelFetch(u_layer_ids, ivec3(texel, u_layer), 0).r == v_object) {
            if (!aboveTangentPlane(texel, vec3(p, zr))) discard;
        }
    }
    // From p through the patch onto the light plane (distance 0), in light units [0, 1].
    float s = zr / (zr - v_depth);
    vec4 onto = p.xyxy + (v_patch - p.xyxy) * s;
    vec4 unit = clamp((onto + u_light_half.xyxy) / (2.0 * u_light_half.xyxy), 0.0, 1.0);
    vec2 covered = unit.zw - unit.xy;
    o_occlusion = vec4(covered.x * covered.y, 0.0, 0.0, 0.0);
}
