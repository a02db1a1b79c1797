// Light geometry in double precision: the exact unshadowed irradiance from polygonal and rect
// area lights (Lambert's formula, clipped to the horizon) and closed forms the tests check against.
#pragma once

#include <span>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace penumbra {

// Irradiance at point p (unit normal n) from a planar, simple polygon of uniform unit radiance
// that emits Lambertian light toward p: E = pi * (form factor from p to the polygon). The polygon
// is first clipped to the receiver's upper hemisphere (the plane through p with normal n), so a
// polygon partly below the horizon is handled exactly and one fully below gives 0. Winding does
// not matter (the result is the polygon's projected solid angle, never negative). Multiply by
// the light's radiance for the physical irradiance. glsl/common/light_irradiance.glsl mirrors it.
double polygonFormFactorIrradiance(std::span<const glm::dvec3> polygon, glm::dvec3 p, glm::dvec3 n);

// Irradiance at p (unit normal n) from a one-sided rectangular light of unit radiance with the
// given corners (e.g. RectLight::corners(), any winding) that emits only toward `forward`: a
// point on or behind the light's plane (dot(p - centre, forward) <= 0) receives 0.
double rectLightIrradiance(std::span<const glm::dvec3, 4> corners, glm::dvec3 forward, glm::dvec3 p,
                           glm::dvec3 n);

// A horizontal rectangle, axis-aligned in x and z, at height centre.y.
struct HorizontalRect {
    glm::dvec3 centre{0.0};
    glm::dvec2 halfSize{0.5};  // half extents along x and z
};

// Visibility of a horizontal, downward-facing rect light seen from `receiver` past one parallel,
// infinitely thin rect occluder: the fraction of the light's AREA not hidden by the occluder
// (the product's definition of visibility; not irradiance-weighted). The occluder is projected
// from the receiver onto the light's plane (it scales by (light.y - r.y) / (occluder.y - r.y)
// about the receiver) and intersected with the light. An occluder at or above the light, or at
// or below the receiver, hides nothing. Throws std::invalid_argument unless the receiver lies
// strictly below the light.
double parallelRectOccluderVisibility(const HorizontalRect& light, const HorizontalRect& occluder,
                                      glm::dvec3 receiver);

// The same for a square light (half size lightHalfSize) and a square occluder.
double parallelSquareOccluderVisibility(glm::dvec3 lightCentre, double lightHalfSize,
                                        glm::dvec3 occluderCentre, double occluderHalfSize,
                                        glm::dvec3 receiver);

}  // namespace penumbra
