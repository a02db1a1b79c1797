// Exact unshadowed irradiance from a one-sided rectangular area light (Lambert's polygon formula,
// clipped to the receiver's horizon): include-only, the float twin of renderer/core/light_geometry.
#ifndef PENUMBRA_LIGHT_IRRADIANCE_GLSL
#define PENUMBRA_LIGHT_IRRADIANCE_GLSL

// Edge a -> b (both relative to the receiver) adds theta * dot(n, normalize(cross(a, b))) to
// Lambert's sum, theta the angle between a and b. cross(a, b - a) equals cross(a, b) but keeps
// its precision for a short edge far away; atan(|a x b|, a . b) is accurate at every angle
// (acos is not near 0 and pi) and needs no normalisation. An edge whose ends are (nearly)
// parallel adds (nearly) nothing and one through the receiver has no plane: both add 0.
float lightIrradianceEdge(vec3 a, vec3 b, vec3 n) {
    vec3 c = cross(a, b - a);
    float lenC = length(c);
    if (!(lenC > 1e-7 * length(a) * length(b))) return 0.0;
    float theta = atan(lenC, dot(a, b));
    return theta * dot(n, c) / lenC;
}

// Irradiance at p (unit normal n) from a rect light of unit radiance with the given corners (in
// either winding) emitting toward `forward`; multiply by the radiance (color * intensity).
// Points on or behind the light's plane get 0. The quad is clipped to the receiver's upper
// hemisphere first, so a light partly below the horizon is exact and one fully below gives 0.
float rectLightIrradiance(vec3 corners[4], vec3 forward, vec3 p, vec3 n) {
    vec3 centre = 0.25 * (corners[0] + corners[1] + corners[2] + corners[3]);
    if (!(dot(p - centre, forward) > 0.0)) return 0.0;

    // Sutherland-Hodgman against the horizon: keep dot(v, n) >= 0, v = corner - p. A convex quad
    // gives at most 5 vertices; 6 covers the alternating signs rounding can produce when the
    // light's plane nearly contains the horizon (where the result is ~0 anyway).
    vec3 v[6];
    int count = 0;
    for (int i = 0; i < 4; ++i) {
        vec3 a = corners[i] - p;
        vec3 b = corners[(i + 1) % 4] - p;
        float da = dot(a, n);
        float db = dot(b, n);
        if (da >= 0.0) v[count++] = a;
        if ((da >= 0.0) != (db >= 0.0)) v[count++] = a + (b - a) * (da / (da - db));
    }
    if (count < 3) return 0.0;

    float sum = 0.0;
    for (int i = 0; i < count; ++i) {
        sum += lightIrradianceEdge(v[i], v[(i + 1) % count], n);
    }
    // The sign follows the winding seen from p; the projected solid angle is the magnitude.
    return 0.5 * abs(sum);
}

#endif  // PENUMBRA_LIGHT_IRRADIANCE_GLSL
