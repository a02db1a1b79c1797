// The share of a rect light's area above a receiver's tangent plane, in closed form
// (include-only): the part below is hidden by the receiver's own surface for a closed object.
#ifndef PENUMBRA_LIGHT_HORIZON_GLSL
#define PENUMBRA_LIGHT_HORIZON_GLSL

// The integral of clamp(t, 0, 1) from 0 to t.
float horizonRamp(float t) {
    float u = clamp(t, 0.0, 1.0);
    return 0.5 * u * u + max(t - 1.0, 0.0);
}

// With the light as the unit square (x, y in [0, 1]) and the height above the plane
// h0 + hx x + hy y, the area of the square where the height is >= 0.
float horizonArea(float h0, float hx, float hy) {
    // Wholly above or below at its corners: nothing to integrate. Not left to the ramp below: a
    // plane nearly parallel to the light (a slope of 1e-7, a float rounding of a normal) put a
    // near 1e7, where R(a + b) - R(a) has no digit left (float's spacing there is 1), and a lit
    // face came out 0 or clamped from 2 (LightHorizonGL.ThePlaneNearlyParallel...).
    if (h0 + min(hx, 0.0) + min(hy, 0.0) >= 0.0) return 1.0;
    if (h0 + max(hx, 0.0) + max(hy, 0.0) <= 0.0) return 0.0;
    // Integrate along the axis of the larger slope: the covered length across it is
    // clamp(a + b y, 0, 1) with |b| <= 1, whose integral over y in [0, 1] is
    // (R(a + b) - R(a)) / b, R = horizonRamp.
    if (abs(hx) < abs(hy)) {
        float t = hx;
        hx = hy;
        hy = t;
    }
    if (abs(hx) < 1e-12) return step(0.0, h0);
    float a = hx > 0.0 ? 1.0 + h0 / hx : -h0 / hx, b = (hx > 0.0 ? hy : -hy) / hx;
    if (abs(b) < 1e-3) return clamp(a + 0.5 * b, 0.0, 1.0);  // (R's difference cancels)
    return clamp((horizonRamp(a + b) - horizonRamp(a)) / b, 0.0, 1.0);
}

// The share of the parallelogram CORNER + x EDGE_X + y EDGE_Y (x, y in [0, 1]) above the
// plane through P with unit normal N.
float lightShareAboveHorizon(vec3 corner, vec3 edge_x, vec3 edge_y, vec3 p, vec3 n) {
    return horizonArea(dot(corner - p, n), dot(edge_x, n), dot(edge_y, n));
}

// The same for a light of SIZE along RIGHT and UP (unit axes) centred at CENTRE.
float centredLightShareAboveHorizon(vec3 centre, vec3 right, vec3 up, vec2 size, vec3 p, vec3 n) {
    vec3 ex = size.x * right, ey = size.y * up;
    return lightShareAboveHorizon(centre - 0.5 * (ex + ey), ex, ey, p, n);
}

#endif  // PENUMBRA_LIGHT_HORIZON_GLSL
