// Shading of one G-buffer point by every light (include-only, shared by shade.frag and
// shade_samples.frag): beauty = albedo/pi * sum_i L_i E_i B_i with E_i the exact unshadowed
// irradiance of rect light i (clipped to the horizon) and B_i the visible share of what the
// light contributes (beautyVisibility); and the irradiance-weighted visibility
// sum(E_i V_i) / sum(E_i) of the area fractions V_i.
#ifndef PENUMBRA_SHADING_GLSL
#define PENUMBRA_SHADING_GLSL

#include "common/bindings.glsl"
#include "common/caster_flags.glsl"
#include "common/geometric_normal.glsl"
#include "common/light_horizon.glsl"
#include "common/light_irradiance.glsl"

struct GpuLight {
    vec4 corners[4];
    vec4 forward;
    vec4 radiance;  // rgb, w = luminance
};
layout(std430, binding = BINDING_LIGHTS) readonly buffer Lights { GpuLight u_lights[]; };

// One layer per light: r = V, the visible area fraction (the papers' quantity); g, b = the sums
// of w_k c_k lit_k and w_k c_k over the light's samples k (c_k: the sample's unshadowed
// contribution cos cos / r^2) and a > 0, written by techniques that sample the light (a = 0
// from the others).
layout(binding = UNIT_SHADE_VISIBILITY) uniform sampler2DArray u_visibility;
// The lights' count: compiled in (LIGHT_COUNT, shade.cpp: a program per count up to a few) or a
// uniform. A constant trip count lets the compiler unroll the loop and index the lights at
// constant offsets: the shade pass at 1024 x 768 with one light 40 -> 29 ms on llvmpipe.
#ifdef LIGHT_COUNT
#define SHADE_LIGHT_COUNT LIGHT_COUNT
#else
uniform int u_light_count;
#define SHADE_LIGHT_COUNT u_light_count
#endif
// The layer holding the environment's irradiance per pixel (rgb: shadowed, a: unshadowed
// luminance; written by `exact`, or folded from the environment's lights, environment_fold.frag),
// or -1.
uniform int u_env_layer = -1;

const float kPi = 3.14159265358979;

// The share of light L's contribution at POS (geometric normal N: the plane the technique's
// horizon rule used) that reaches it, from the technique's
// layer VIS. Where the technique sampled the light, the contribution-weighted share of its
// samples; where none of them lies above the horizon, nothing says the part above is hidden
// (E has left out the rest): 1. Otherwise, on an object that casts (CASTS), V counts the
// light's part below the tangent plane as hidden (the receiver's own surface hides it from
// every light sample) while E already leaves it out: V is divided by the share of the light
// above the plane, so that part is not removed twice. An object that casts no shadow does not
// hide the light from itself: its V is the share that casters leave, B = V.
float beautyVisibility(vec4 vis, GpuLight l, vec3 pos, vec3 n, bool casts) {
    if (vis.a > 0.0) return vis.b > 0.0 ? clamp(vis.g / vis.b, 0.0, 1.0) : 1.0;
    if (!casts) return clamp(vis.r, 0.0, 1.0);
    float share = lightShareAboveHorizon(l.corners[0].xyz, l.corners[1].xyz - l.corners[0].xyz,
                                         l.corners[3].xyz - l.corners[0].xyz, pos, n);
    return share > 0.0 ? clamp(vis.r / share, 0.0, 1.0) : 0.0;
}

// Light L's irradiance at POS (unit normal N; plane G and CASTS for the horizon rule) with its
// visibility layer VIS: rgb = L's radiance x E x B (shadowed), a = its luminance x E.
vec4 lightIrradiance(GpuLight l, vec4 vis, vec3 pos, vec3 n, vec3 g, bool casts) {
    vec3 c[4] = vec3[4](l.corners[0].xyz, l.corners[1].xyz, l.corners[2].xyz, l.corners[3].xyz);
    float e = rectLightIrradiance(c, l.forward.xyz, pos, n);
    return vec4(l.radiance.rgb * e * beautyVisibility(vis, l, pos, g, casts), l.radiance.w * e);
}

// Radiance leaving POS (unit normal N, linear ALBEDO) lit by every light, with the visibility
// layers of pixel VIS_PIX (fully visible where VIS_PIX.x < 0); VISIBILITY gets the
// irradiance-weighted visibility (the plain mean where no light reaches the point unshadowed).
vec3 shadePoint(vec3 pos, vec3 n, vec3 albedo, int id, ivec2 vis_pix, out float visibility) {
    bool casts = objectCasts(id);
    // The plane of V's horizon rule: the geometric normal of the pixel whose visibility is used.
    vec3 g = vis_pix.x < 0 ? n : geometricNormal(vis_pix);
    vec3 radiance = vec3(0.0);
    float num = 0.0, den = 0.0, plain = 0.0;
    for (int i = 0; i < SHADE_LIGHT_COUNT; ++i) {
        vec4 layer = vis_pix.x < 0 ? vec4(1.0, 1.0, 1.0, 1.0)
                                   : texelFetch(u_visibility, ivec3(vis_pix, i), 0);
        vec4 term = lightIrradiance(u_lights[i], layer, pos, n, g, casts);
        float v = layer.r;
        radiance += albedo / kPi * term.rgb;
        num += term.a * v;
        den += term.a;
        plain += v;
    }
    int terms = SHADE_LIGHT_COUNT;
    // A sample no representative pixel stands for (VIS_PIX.x < 0) has no environment term: the
    // layer is per pixel, and such slivers are rare.
    if (u_env_layer >= 0 && vis_pix.x >= 0) {
        vec4 env = texelFetch(u_visibility, ivec3(vis_pix, u_env_layer), 0);
        radiance += albedo / kPi * env.rgb;
        float shadowed = dot(env.rgb, vec3(0.2126, 0.7152, 0.0722));
        num += shadowed;
        den += env.a;
        plain += env.a > 0.0 ? clamp(shadowed / env.a, 0.0, 1.0) : 1.0;
        ++terms;
    }
    visibility = clamp(den > 0.0 ? num / den : plain / float(max(terms, 1)), 0.0, 1.0);
    return radiance;
}

#endif  // PENUMBRA_SHADING_GLSL
