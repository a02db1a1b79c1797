#version 450 core
// `ssm` visibility: each camera pixel of a receiver is projected from the light's centre into
// the soft shadow map (two maps merged by max when two-sided, 3.5); visibility = 1 - occlusion.
// With several receiver layers, each of the four bilinear texels takes the layer whose receiver
// depth matches the pixel's, its own object's layers first (a pixel of a casting object facing
// away from the light's centre, which no layer holds, takes only those; matching none, it sees
// the light's part above its horizon; a receiver's, which its object does not hide, matches as
// a light-facing one); a pixel no layer matches takes the nearest layer, which for a pixel
// beyond a full stack of layers is the deepest: what shadows that surface shadows the pixel
// behind it too (a lower bound on its occlusion). Pixels of objects that receive no shadow are
// lit, less the light below their horizon on those that cast. Diagnostic 0: the summed
// occlusion; 1: the receiver layer used (of the texel weighing most; -1 where none).
#include "techniques/ssm/bindings.glsl"
#ifndef TWO_SIDED
#define TWO_SIDED 0
#endif
// COVER 1: the cover pass (soft_shadow_lookup.cpp) writes the pixels whose bilinear texels hide
// nothing in any layer and whose own object's layer matches at once, and discards the others
// for the full program (llvmpipe runs every inlined branch of a shader for every fragment).
#ifndef COVER
#define COVER 0
#endif
#if !COVER
layout(early_fragment_tests) in;  // the cover pass's depth (passes::drawCovered), tested before
#endif
#include "common/caster_flags.glsl"
#include "common/geometric_normal.glsl"
#include "common/light_horizon.glsl"

in vec2 v_uv;
layout(binding = SSM_UNIT_VISIBILITY_POSITION) uniform sampler2D u_position;
layout(binding = SSM_UNIT_VISIBILITY_ID) uniform isampler2D u_id;
// 1 per object id that receives shadows
layout(binding = SSM_UNIT_VISIBILITY_RECEIVES) uniform sampler2D u_receives;
// One layer per receiver layer
layout(binding = SSM_UNIT_VISIBILITY_SSM) uniform sampler2DArray u_ssm;
#if TWO_SIDED
layout(binding = SSM_UNIT_VISIBILITY_SSM_BACK) uniform sampler2DArray u_ssm_back;
#endif
// Receiver depth per layer, 1 = none
layout(binding = SSM_UNIT_VISIBILITY_LAYERS) uniform sampler2DArray u_layers;
layout(binding = SSM_UNIT_VISIBILITY_LAYER_IDS) uniform isampler2DArray u_layer_ids;
#include "common/light_frame.glsl"
uniform vec2 u_light_size;
uniform vec2 u_ssm_lo;
uniform vec2 u_ssm_size;
uniform int u_shadowed;     // 0: no occluder lies between the light and a receiver
uniform int u_layer_count;  // receiver layers
uniform int u_layered;  // 1: LAYERS > 1 (depth-matched layers; objects that cast also receive)
uniform float u_near;       // the soft-shadow window's depth range
uniform float u_range;
uniform float u_depth_bias;

layout(location = 0) out vec4 o_visibility;
layout(location = 1) out vec4 o_occlusion;
layout(location = 2) out vec4 o_layer;

float occlusionOf(int layer, ivec2 texel) {
    float o = texelFetch(u_ssm, ivec3(texel, layer), 0).r;
#if TWO_SIDED
    o = max(o, texelFetch(u_ssm_back, ivec3(texel, layer), 0).r);
#endif
    return o;
}

// The bilinear occlusion at UV over the texels whose best-matching layer lies within TOL of
// the pixel's depth DP (and holds object OWN, unless OWN < 0); false when no texel matches.
// LAYER: the layer of the heaviest texel.
bool layeredOcclusion(vec2 uv, float dp, float tol, int own, out float occlusion,
                      out int layer) {
    ivec2 res = textureSize(u_ssm, 0).xy;
    vec2 t = uv * vec2(res) - 0.5;
    ivec2 base = ivec2(floor(t));
    vec2 f = t - vec2(base);
    float sum = 0.0, weights = 0.0, heaviest = 0.0;
    layer = -1;
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 2; ++x) {
            ivec2 q = clamp(base + ivec2(x, y), ivec2(0), res - 1);
            float w = (x == 1 ? f.x : 1.0 - f.x) * (y == 1 ? f.y : 1.0 - f.y);
            int best = -1;
            float best_diff = tol;
            for (int k = 0; k < u_layer_count; ++k) {
                float dk = texelFetch(u_layers, ivec3(q, k), 0).r;
                if (dk >= 1.0) break;  // no deeper layer here
                float diff = abs(dk - dp);
                if (own >= 0 && texelFetch(u_layer_ids, ivec3(q, k), 0).r != own) continue;
                if (diff <= best_diff) {
                    best_diff = diff;
                    best = k;
                }
            }
            if (best < 0) continue;
            sum += w * occlusionOf(best, q);
            weights += w;
            if (w >= heaviest) {
                heaviest = w;
                layer = best;
            }
        }
    occlusion = weights > 0.0 ? sum / weights : 0.0;
    return weights > 0.0;
}

// Whether any of the bilinear texels at UV hides some of the light in any layer.
bool anyOcclusion(vec2 uv) {
    ivec2 res = textureSize(u_ssm, 0).xy;
    ivec2 base = ivec2(floor(uv * vec2(res) - 0.5));
    float most = 0.0;
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 2; ++x) {
            ivec2 q = clamp(base + ivec2(x, y), ivec2(0), res - 1);
            for (int k = 0; k < u_layer_count; ++k) most = max(most, occlusionOf(k, q));
        }
    return most > 0.0;
}

// The share of the light above the tangent plane of P (unit normal N).
float shareAboveHorizon(vec3 p, vec3 n) {
    return centredLightShareAboveHorizon(u_light_centre, u_light_right, u_light_up, u_light_size,
                                         p, n);
}

// The pixel's visibility V before its horizon, the receiver layer it took (-1: none) and whether
// the light's share above its horizon multiplies V; false where the pixel is settled elsewhere
// (COVER 1: by the full program, which the discard leaves it to).
bool receiverVisibility(vec3 pos, vec3 n, int id, out float v, out int layer, out bool horizon) {
    v = 1.0;
    layer = -1;
    horizon = false;
    if (u_shadowed == 0 || id < 0 || texelFetch(u_receives, ivec2(id, 0), 0).r < 0.5) {
        // No caster shadows it, but an object that casts hides from itself the light's part
        // below its surface's horizon (role `occluder`, or nothing shadowed), as every
        // technique's casters do.
        horizon = id >= 0 && objectCasts(id);
        return true;
    }
    vec3 d = pos - u_light_centre;
    float z = dot(d, u_light_forward);
    if (z <= 0.0) return true;
    vec2 uv = (vec2(dot(d, u_light_right), dot(d, u_light_up)) / z - u_ssm_lo) / u_ssm_size;
    if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0)))) return true;
    float occlusion;
    if (u_layered == 0) {
        // The paper: one receiver map, looked up without a depth match.
        occlusion = texture(u_ssm, vec3(uv, 0.0)).r;
#if TWO_SIDED
        occlusion = max(occlusion, texture(u_ssm_back, vec3(uv, 0.0)).r);
#endif
        layer = 0;
    } else {
        // Match within 8 soft-map texels of the receiver's slope-free footprint plus the bias.
        float texel = max(u_ssm_size.x, u_ssm_size.y) / float(textureSize(u_ssm, 0).x) * z;
        float tol = (8.0 * texel + u_depth_bias * z) / u_range;
        float dp = (z - u_near) / u_range;
#if COVER
        // Unoccluded here: the full program's first match gives its layer and an occlusion of
        // 0, and every later way would give 0 too; else the full program decides.
        if (anyOcclusion(uv) || !layeredOcclusion(uv, dp, tol, id, occlusion, layer))
            return false;
#else
        // Layers of the pixel's own object first: another object's layer at its depth can lie
        // in the pixel's object's own shadow (where a steep wall meets the floor, the floor's
        // layer matched the wall's foot and darkened it). A surface facing away from the
        // light's centre is in no layer (they hold light-facing surfaces; an open sheet's, its
        // side the light sees), so it matches only its own object's (its lit side next to it,
        // whose occlusion by other casters it shares); matching none, it sees the light's part
        // above its horizon. Only on objects that cast: a receiver hides nothing, not even from
        // itself (exact's rays pass through it), so its pixels facing away match as light-facing
        // ones (a wall between the light and the camera took 0 where no layer of its own
        // matched: mix34).
        vec3 to_light = u_light_centre - pos;
        bool casts = objectCasts(id);
        bool away = casts && dot(n, to_light) <= 0.0;
        // Where none of its own matches, its own within the depth its surface spans over two
        // texels: a face nearly edge-on to the light's centre spans many texels' depth in one
        // (a wall of random scene rand111, 0.75 m high in about a texel: no layer matched and
        // the nearest, another object's, striped it). Only then: at once, a texel of another
        // part of the object (a duck's head over its steep body) joined the bilinear sum.
        // tan of the angle to the light, capped at 1000 (a face exactly edge-on).
        float c = abs(dot(n, normalize(to_light)));
        float slope = min(sqrt(max(1.0 - c * c, 0.0)) / max(c, 1e-3), 1000.0);
        float own_tol = tol + 2.0 * texel * slope / u_range;
        if (!layeredOcclusion(uv, dp, tol, id, occlusion, layer) &&
            !(own_tol > tol && layeredOcclusion(uv, dp, own_tol, id, occlusion, layer)) &&
            (away || !layeredOcclusion(uv, dp, tol, -1, occlusion, layer))) {
            int nearest = -1;
            float nearest_diff = 2.0;
            ivec2 res = textureSize(u_layers, 0).xy;
            ivec2 q = clamp(ivec2(uv * vec2(res)), ivec2(0), res - 1);
            for (int k = 0; k < u_layer_count; ++k) {
                float dk = texelFetch(u_layers, ivec3(q, k), 0).r;
                if (dk >= 1.0) break;
                if (abs(dk - dp) < nearest_diff) {
                    nearest_diff = abs(dk - dp);
                    nearest = k;
                }
            }
            if (away || nearest < 0) {
                layer = -1;  // (a match of weight 0 may have named one)
                horizon = casts;  // a receiver: all of the light
                return true;
            }
            occlusion = occlusionOf(nearest, q);
            layer = nearest;
        }
#endif
    }
    v = 1.0 - clamp(occlusion, 0.0, 1.0);
    // An object's patches never shadow the surface they lie on (splat.vert): the light's part
    // below that surface's horizon, which the object itself hides, is taken in closed form, as
    // css does; the other casters' occlusion falls on the rest alike.
    horizon = u_layered != 0 && objectCasts(id);
    return true;
}

void main() {
    ivec2 pix = ivec2(gl_FragCoord.xy);
    vec4 pos = texelFetch(u_position, pix, 0);
    // Outside every object: the values the pass clears to (the cover settles it)
    float v = 0.0;
    int layer = -1;
    if (pos.w != 0.0) {
        bool horizon;
        vec3 n = geometricNormal(pix);
        if (!receiverVisibility(pos.xyz, n, texelFetch(u_id, pix, 0).r, v, layer, horizon)) discard;
        // One call site: a software rasteriser runs every inlined copy for every fragment.
        if (horizon) v *= shareAboveHorizon(pos.xyz, n);
    }
#if !COVER
    else
        discard;  // settled by the cover
#endif
    o_visibility = vec4(v, 0.0, 0.0, 0.0);
    o_occlusion = vec4(pos.w != 0.0 ? 1.0 - v : 0.0, 0.0, 0.0, 0.0);
    o_layer = vec4(float(layer), 0.0, 0.0, 0.0);
}
