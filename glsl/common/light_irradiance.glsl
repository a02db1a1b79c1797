// Exact unshadowed irradiance from a one-sided rectangular area light (Lambert's polygon formula,
// clipped to the receiver's horizon): include-only, the float twin of renderer/core/light_geometry.
#ifndef PENUMBRA_LIGHT_IRRADIANCE_GLSL
#define PENUMBRA_LIGHT_IRRADIANCE_GLSL

// Edge a -> a + e (a relative to the receiver) adds theta * dot(n, normalize(cross(a, b)))
// to Lambert's sum, theta the angle between a and b = a + e. cross(a, e) equals cross(a, b) but
// keeps its precision for a short edge far away (so e is passed, not b: a part of an edge cut
// at the horizon has e = (b - a) x its share, not a difference of nearby points);
// atan(|a x b|, a . b) is accurate at every angle (acos is not near 0 and pi) and needs no
// normalisation. An edge whose ends are (nearly) parallel adds (nearly) nothing and one through
// the receiver has no plane: both add 0.
float lightIrradianceEdgeDir(vec3 a, vec3 e, vec3 n) {
    vec3 c = cross(a, e);
    float lenC = length(c);
    vec3 b = a + e;
    if (!(lenC > 1e-7 * length(a) * length(b))) return 0.0;
    float theta = atan(lenC, dot(a, b));
    return theta * dot(n, c) / lenC;
}
float lightIrradianceEdge(vec3 a, vec3 b, vec3 n) {
    return lightIrradianceEdgeDir(a, b - a, n);
}

// Edge a -> b of the light clipped to the receiver's upper hemisphere (da, db: heights of a and
// b above the horizon plane). Records where the boundary leaves (exit) and re-enters (entry)
// the hemisphere, so the caller can close the clipped polygon along the horizon. Without a
// branch: an edge wholly above is the edge itself, one wholly below adds 0, and the points are
// chosen by selects (on a SIMD rasteriser such as llvmpipe a block of pixels with any clipped
// one ran both sides of a branch: the shade pass took 41 ms at 1024 x 768 instead of 33).
float lightIrradianceClippedEdge(vec3 a, vec3 b, float da, float db, vec3 n, inout vec3 exit_point,
                                 inout vec3 entry_point) {
    bool keep_a = da >= 0.0, keep_b = db >= 0.0;
    // Where the edge crosses the plane, at share t of it; used only when exactly one end is
    // below (da != db).
    float t = da / (keep_a == keep_b ? 1.0 : da - db);
    vec3 e = b - a, x = a + e * t;
    exit_point = keep_a && !keep_b ? x : exit_point;
    entry_point = !keep_a && keep_b ? x : entry_point;
    float share = (keep_b ? 1.0 : t) - (keep_a ? 0.0 : t);
    float kept = lightIrradianceEdgeDir(keep_a ? a : x, e * share, n);
    return keep_a || keep_b ? kept : 0.0;
}

// Irradiance at p (unit normal n) from a rect light of unit radiance with the given corners (in
// either winding) emitting toward `forward`; multiply by the radiance (color * intensity).
// Points on or behind the light's plane get 0. The quad is clipped to the receiver's upper
// hemisphere first (Sutherland-Hodgman, done edge by edge without a vertex array: dynamic
// indexing of local arrays is slow on SIMD software rasterisers such as llvmpipe), so a light
// partly below the horizon is exact and one fully below gives 0.
float rectLightIrradiance(vec3 corners[4], vec3 forward, vec3 p, vec3 n) {
    vec3 centre = 0.25 * (corners[0] + corners[1] + corners[2] + corners[3]);
    if (!(dot(p - centre, forward) > 0.0)) return 0.0;
    vec3 a0 = corners[0] - p, a1 = corners[1] - p, a2 = corners[2] - p, a3 = corners[3] - p;
    vec4 d = vec4(dot(a0, n), dot(a1, n), dot(a2, n), dot(a3, n));
    if (all(lessThan(d, vec4(0.0)))) return 0.0;
    // A convex quad crosses the horizon plane once each way: its clipped boundary is the
    // kept parts of its edges plus the segment from the exit point back to the entry point
    // (from 0 to 0, adding nothing, when no corner is below).
    vec3 exit_point = vec3(0.0), entry_point = vec3(0.0);
    float sum = lightIrradianceClippedEdge(a0, a1, d.x, d.y, n, exit_point, entry_point) +
                lightIrradianceClippedEdge(a1, a2, d.y, d.z, n, exit_point, entry_point) +
                lightIrradianceClippedEdge(a2, a3, d.z, d.w, n, exit_point, entry_point) +
                lightIrradianceClippedEdge(a3, a0, d.w, d.x, n, exit_point, entry_point);
    sum += lightIrradianceEdge(exit_point, entry_point, n);
    // The sign follows the winding seen from p; the projected solid angle is the magnitude.
    return 0.5 * abs(sum);
}

#endif  // PENUMBRA_LIGHT_IRRADIANCE_GLSL
