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

// Edge a -> b of the light clipped to the receiver's upper hemisphere (da, db: heights of a and
// b above the horizon plane). Records where the boundary leaves (exit) and re-enters (entry)
// the hemisphere, so the caller can close the clipped polygon along the horizon.
float lightIrradianceClippedEdge(vec3 a, vec3 b, float da, float db, vec3 n, inout vec3 exit_point,
                                 inout vec3 entry_point) {
    if (da >= 0.0 && db >= 0.0) return lightIrradianceEdge(a, b, n);
    if (da < 0.0 && db < 0.0) return 0.0;
    vec3 x = a + (b - a) * (da / (da - db));
    if (da >= 0.0) {
        exit_point = x;
        return lightIrradianceEdge(a, x, n);
    }
    entry_point = x;
    return lightIrradianceEdge(x, b, n);
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
    float sum;
    if (all(greaterThanEqual(d, vec4(0.0)))) {
        sum = lightIrradianceEdge(a0, a1, n) + lightIrradianceEdge(a1, a2, n) +
              lightIrradianceEdge(a2, a3, n) + lightIrradianceEdge(a3, a0, n);
    } else {
        // A convex quad crosses the horizon plane once each way: its clipped boundary is the
        // kept parts of its edges plus the segment from the exit point back to the entry point.
        vec3 exit_point = vec3(0.0), entry_point = vec3(0.0);
        sum = lightIrradianceClippedEdge(a0, a1, d.x, d.y, n, exit_point, entry_point) +
              lightIrradianceClippedEdge(a1, a2, d.y, d.z, n, exit_point, entry_point) +
              lightIrradianceClippedEdge(a2, a3, d.z, d.w, n, exit_point, entry_point) +
              lightIrradianceClippedEdge(a3, a0, d.w, d.x, n, exit_point, entry_point);
        sum += lightIrradianceEdge(exit_point, entry_point, n);
    }
    // The sign follows the winding seen from p; the projected solid angle is the magnitude.
    return 0.5 * abs(sum);
}

#endif  // PENUMBRA_LIGHT_IRRADIANCE_GLSL
