#version 450 core
// `ssm` splat: the share of the light one micro-patch hides from the receiver seen through this
// soft-shadow-map texel. The patch is back-projected from the receiver onto the light and the
// covered area is the product of two interval intersections (Atty et al. 3.4, 4.2); the host
// sums the patches with additive blending, once per receiver layer.
#include "techniques/ssm/bindings.glsl"
// Linear receiver depth, 1 = none
layout(binding = SSM_UNIT_SPLAT_RECEIVER) uniform sampler2DArray u_receiver;
uniform int u_layer;  // the receiver layer splatted into
uniform vec2 u_light_half;
uniform vec2 u_ssm_lo;
uniform vec2 u_ssm_texel;  // one soft-shadow-map texel at distance 1
uniform float u_receiver_near;
uniform float u_receiver_range;
uniform float u_depth_bias;  // a patch must be this fraction of z_R nearer than the receiver

layout(binding = SSM_UNIT_SPLAT_LAYER_IDS) uniform isampler2DArray u_layer_ids;
// Per receiver layer: the unit normal of its surface in the light's frame (receiver_planes.comp)
layout(binding = SSM_UNIT_SPLAT_PLANES) uniform sampler2DArray u_planes;
uniform int u_layer_count;

flat in vec4 v_rect;  // the patch in window units at distance 1 (x0, y0, x1, y1)
flat in float v_depth;
flat in float v_depth_near;  // a merged patch's nearest micro-patch (lod.comp); else v_depth
flat in int v_object;
flat in int v_children;  // micro-patches per side merged into this one (lod.comp)
flat in ivec2 v_texel;   // its (first) occluder texel
flat in float v_reach;   // far side: its surface's depth span beyond it (splat.vert)

// A merged patch's micro-patches (a receiver near it in depth counts them one by one)
layout(binding = SSM_UNIT_SPLAT_OCC_DEPTH) uniform sampler2D u_occ_depth;  // linear
uniform float u_occ_near;
uniform float u_occ_range;
uniform vec2 u_occ_lo;     // occluder-map window at distance 1
uniform vec2 u_occ_texel;  // one texel of it

layout(location = 0) out vec4 o_occlusion;

// Receivers nearer than this many depth spans of a merged patch count its micro-patches.
const float kNearSpans = 4.0;

// The share of the light that rectangle R (x0, y0, x1, y1, light's frame at distance Z) hides
// from the receiver P: back-projected from P onto the light (distance 0), in light units [0, 1].
float covered(vec4 r, float z, vec3 p) {
    float s = p.z / (p.z - z);
    vec4 onto = p.xyxy + (r - p.xyxy) * s;
    vec4 unit = clamp((onto + u_light_half.xyxy) / (2.0 * u_light_half.xyxy), 0.0, 1.0);
    vec2 c = unit.zw - unit.xy;
    return c.x * c.y;
}

// Whether the micro-patch R at distance Z lies wholly above the tangent plane N of the
// receiver P by MARGIN (its lowest corner: each axis's nearer side).
bool above(vec3 n, vec4 r, float z, vec3 p, float margin) {
    vec2 lo = min(n.xy * r.xy, n.xy * r.zw);
    return lo.x + lo.y + n.z * z - dot(n, p) > margin;
}

// The share of the light hidden from the receiver P at texel T, a surface of the patch's own
// object, by the patch R at distance Z where its micro-patches lie wholly above P's tangent
// plane (receiver_planes.comp) by a margin for that plane's estimate: the light they hide lies
// above P's horizon, none of it the part the visibility pass takes in closed form. A patch
// merged by lod.comp counts each of its v_children^2 micro-patches so, a row at a time: in a
// row the ones above the plane are a run, as each one's lowest corner rises linearly.
float ownObjectOcclusion(ivec2 t, vec4 r, float z, vec3 p) {
    vec3 n = texelFetch(u_planes, ivec3(t, u_layer), 0).xyz;
    if (n == vec3(0.0)) return 0.0;
    float margin = (u_depth_bias + 2.0 * max(u_ssm_texel.x, u_ssm_texel.y)) * p.z;
    if (v_children == 1) return above(n, r, z, p, margin) ? covered(r, z, p) : 0.0;
    int k = v_children;
    vec2 w = (r.zw - r.xy) / float(k);  // one micro-patch
    float rise = n.x * w.x;             // of the lowest corner from a column to the next
    float sum = 0.0;
    for (int j = 0; j < k; ++j) {
        float y0 = r.y + float(j) * w.y, y1 = y0 + w.y;
        // Column 0's lowest corner over the plane, less the margin.
        float h =
            n.x * r.x + min(0.0, rise) + min(n.y * y0, n.y * y1) + n.z * z - dot(n, p) - margin;
        int first = 0, last = k - 1;  // the run above the plane: h + rise * i > 0
        if (rise > 0.0)
            first = max(int(floor(-h / rise)) + 1, 0);
        else if (rise < 0.0)
            last = min(int(ceil(-h / rise)) - 1, k - 1);
        else if (h <= 0.0)
            continue;
        if (first <= last)
            sum +=
                covered(vec4(r.x + float(first) * w.x, y0, r.x + float(last + 1) * w.x, y1), z, p);
    }
    return sum;
}

// A merged patch's occlusion of the receiver P at texel T micro-patch by micro-patch, at their
// own depths, as the unmerged splat counts them (OWN: P is of the patch's object).
float microPatchesOcclusion(ivec2 t, vec3 p, bool own) {
    vec3 n = texelFetch(u_planes, ivec3(t, u_layer), 0).xyz;
    if (own && n == vec3(0.0)) return 0.0;
    float margin = (u_depth_bias + 2.0 * max(u_ssm_texel.x, u_ssm_texel.y)) * p.z;
    float sum = 0.0;
    for (int j = 0; j < v_children; ++j)
        for (int i = 0; i < v_children; ++i) {
            ivec2 c = v_texel + ivec2(i, j);
            float z = u_occ_near + texelFetch(u_occ_depth, c, 0).r * u_occ_range;
            if (p.z - z <= u_depth_bias * p.z) continue;
            vec2 lo = u_occ_lo + vec2(c) * u_occ_texel;
            vec4 r = vec4(lo, lo + u_occ_texel) * z;
            if (!own || above(n, r, z, p, margin)) sum += covered(r, z, p);
        }
    return sum;
}

void main() {
    ivec2 texel = ivec2(gl_FragCoord.xy);
    float dr = texelFetch(u_receiver, ivec3(texel, u_layer), 0).r;
    if (dr >= 1.0) discard;
    float zr = u_receiver_near + dr * u_receiver_range;
    // No micro-patch in front of it (nor, far side, its surface's span)
    if (zr - v_depth_near <= u_depth_bias * zr + v_reach) discard;
    vec3 p = vec3((u_ssm_lo + (vec2(texel) + 0.5) * u_ssm_texel) * zr, zr);
    // A patch shadows its own object's surface only where it lies wholly above that surface's
    // tangent plane here (a head over the body it rests on, an ear over a head): below the
    // plane it could hide only light below the horizon, which the visibility pass takes in
    // closed form. Not where it merely lies in front of that surface at its texel: a box's top
    // face in front of its steep lit wall striped the wall (random scene rand20: 0.31).
    bool own = u_layer_count > 1 && texelFetch(u_layer_ids, ivec3(texel, u_layer), 0).r == v_object;
    float o;
    if (v_children > 1 &&
        zr - v_depth_near <= kNearSpans * 2.0 * (v_depth - v_depth_near) + u_depth_bias * zr) {
        // Near a merged patch in depth, within a few of its depth spans, its one depth would
        // misplace the micro-patches' back-projections, or count ones the bias drops: count
        // them one by one (at most lod.comp's largest block).
        o = microPatchesOcclusion(texel, p, own);
    } else if (own) {
        if (zr - v_depth <= u_depth_bias * zr) discard;
        o = ownObjectOcclusion(texel, v_rect * v_depth, v_depth, p);
    } else {
        if (zr - v_depth <= u_depth_bias * zr) discard;
        o = covered(v_rect * v_depth, v_depth, p);
    }
    if (o == 0.0) discard;
    o_occlusion = vec4(o, 0.0, 0.0, 0.0);
}
