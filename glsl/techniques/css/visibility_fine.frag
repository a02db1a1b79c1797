#version 450 core
// `css` visibility of the camera pixels that visibility_coarse.frag's samples at even pixels
// can stand for: a pixel takes the mean of the two or four samples around it (its own, at an
// even pixel) when all lie on its object, were evaluated, agree on whether a blocker was found,
// their shadow S spreads by at most u_interpolate and, where they found one, the samples lie
// within SPACING of the narrowest final kernel among them in the map (a shadow's features are
// as wide as its kernel: a thin hard shadow between two lit samples is not interpolated) and,
// on an object that casts, lie on its facet's plane (its test depth follows that plane), times
// its own horizon. The others are
// discarded, which sends them to visibility.frag (css.cpp, passes::drawInTurn). The pixels
// visibility_settled.frag settled (the cleared values) never reach this shader.
// Pixels without a surface get the cleared values. Outputs as visibility.frag's.
#include "techniques/css/visibility.glsl"

// visibility_coarse.frag's samples: (S, z_avg, kernel width, object id + 1)
layout(binding = CSS_UNIT_VISIBILITY_COARSE) uniform sampler2D u_coarse;
uniform float u_interpolate;  // the largest spread of S between samples that is interpolated
#define SPACING 0.25          // the largest distance of samples in the map, in final kernels

layout(location = 0) out vec4 o_visibility;
layout(location = 1) out vec4 o_z_avg;
layout(location = 2) out vec4 o_filter_width;

// Whether the surface at pixel PIX lies on the plane of receiver R (position, facet normal).
bool onPlane(ivec2 pix, Receiver r) {
    vec3 p = texelFetch(u_position, pix, 0).xyz;
    return dot(geometricNormal(pix), r.normal) > 0.9999 &&
           abs(dot(p - r.pos, r.normal)) <= 1e-4 * (1.0 + length(p - r.pos));
}

// The mean of the samples around PIX into S, when they may stand for the pixel of receiver R;
// STEP is the distance in map texels between neighbouring pixels there.
bool interpolated(ivec2 pix, Receiver r, float step, out vec3 s) {
    ivec2 q = pix >> 1, odd = pix & 1;
    if (any(greaterThanEqual(q + odd, textureSize(u_coarse, 0)))) return false;
    vec4 a = texelFetch(u_coarse, q, 0), b = texelFetch(u_coarse, q + ivec2(odd.x, 0), 0);
    vec4 c = texelFetch(u_coarse, q + ivec2(0, odd.y), 0), d = texelFetch(u_coarse, q + odd, 0);
    vec4 shadow = vec4(a.x, b.x, c.x, d.x);
    bvec4 found = greaterThan(vec4(a.y, b.y, c.y, d.y), vec4(0.0));
    if (any(notEqual(vec4(a.w, b.w, c.w, d.w), vec4(float(r.id + 1)))) ||
        any(lessThan(shadow, vec4(0.0))) || (any(found) && !all(found)))
        return false;
    vec2 range = vec2(min(min(shadow.x, shadow.y), min(shadow.z, shadow.w)),
                      max(max(shadow.x, shadow.y), max(shadow.z, shadow.w)));
    if (range.y - range.x > u_interpolate) return false;
    float narrowest = min(min(a.z, b.z), min(c.z, d.z));
    if (found.x && 2.0 * step > SPACING * narrowest) return false;
    if (r.casts && u_self_exclude > 0.0 &&
        !(onPlane(2 * q, r) && onPlane(2 * (q + ivec2(odd.x, 0)), r) &&
          onPlane(2 * (q + ivec2(0, odd.y)), r) && onPlane(2 * (q + odd), r)))
        return false;
    s = 0.25 * (a.xyz + b.xyz + c.xyz + d.xyz);
    return true;
}

void main() {
    ivec2 pix = ivec2(gl_FragCoord.xy);
    Receiver r;
    bool surface = receiverAt(pix, r);
    // The map's texels between neighbouring pixels, from the 2 x 2 quad (uniform control flow;
    // a quad that is not one surface gets a large step and is evaluated).
    vec2 c = surface ? mapTexel(r.pos) : vec2(1e9);
    float step = max(length(dFdx(c)), length(dFdy(c)));
    vec3 s = vec3(1.0, 0.0, 0.0);
    if (!surface)
        r.horizon = 1.0;  // no surface: the cleared values
    else if (r.horizon > 0.0 && !interpolated(pix, r, step, s))
        discard;  // evaluated by visibility.frag
    o_visibility = vec4(r.horizon * s.x, 0.0, 0.0, 0.0);
    o_z_avg = vec4(s.y, 0.0, 0.0, 0.0);
    o_filter_width = vec4(s.z, 0.0, 0.0, 0.0);
}
