// Lambert's polygon formula with horizon clipping (double precision), the one-sided rect light
// built on it, and the closed-form visibility of a parallel rect light past a parallel occluder.
#include "renderer/core/light_geometry.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

namespace penumbra {
namespace {

// Edge a -> b of the polygon, both relative to the receiver, contributes
// theta * dot(n, normalize(cross(a, b))) to Lambert's sum, theta the angle between a and b.
// cross(a, b) is computed as cross(a, b - a): the same vector, but without the cancellation that
// loses it for a short edge far away. theta = atan2(|a x b|, a . b) is accurate at every angle
// (acos is not near 0 and pi) and needs no normalisation. An edge whose ends are (nearly)
// parallel adds (nearly) nothing, and one through the receiver has no defined plane: both add 0.
double edgeTerm(glm::dvec3 a, glm::dvec3 b, glm::dvec3 n) {
    const glm::dvec3 c = glm::cross(a, b - a);
    const double lenC = glm::length(c);
    if (!(lenC > 1e-14 * glm::length(a) * glm::length(b))) return 0.0;
    const double theta = std::atan2(lenC, glm::dot(a, b));
    return theta * glm::dot(n, c) / lenC;
}

}  // namespace

double polygonFormFactorIrradiance(std::span<const glm::dvec3> polygon, glm::dvec3 p,
                                   glm::dvec3 n) {
    const size_t count = polygon.size();
    if (count < 3) return 0.0;
    const double nLen = glm::length(n);
    if (!(nLen > 0.0)) return 0.0;
    n /= nLen;

    // Sutherland-Hodgman against the horizon: keep the part with dot(v, n) >= 0, v = x - p.
    std::vector<glm::dvec3> clipped;
    clipped.reserve(count + 2);
    for (size_t i = 0; i < count; ++i) {
        const glm::dvec3 a = polygon[i] - p;
        const glm::dvec3 b = polygon[(i + 1) % count] - p;
        const double da = glm::dot(a, n);
        const double db = glm::dot(b, n);
        if (da >= 0.0) clipped.push_back(a);
        if ((da >= 0.0) != (db >= 0.0)) clipped.push_back(a + (b - a) * (da / (da - db)));
    }
    if (clipped.size() < 3) return 0.0;

    double sum = 0.0;
    for (size_t i = 0; i < clipped.size(); ++i) {
        sum += edgeTerm(clipped[i], clipped[(i + 1) % clipped.size()], n);
    }
    // The sum's sign follows the winding as seen from p; the projected solid angle of the clipped
    // polygon is its magnitude.
    return 0.5 * std::abs(sum);
}

double rectLightIrradiance(std::span<const glm::dvec3, 4> corners, glm::dvec3 forward, glm::dvec3 p,
                           glm::dvec3 n) {
    const glm::dvec3 centre = 0.25 * (corners[0] + corners[1] + corners[2] + corners[3]);
    if (!(glm::dot(p - centre, forward) > 0.0)) return 0.0;  // on or behind the emitting face
    return polygonFormFactorIrradiance(corners, p, n);
}

double parallelRectOccluderVisibility(const HorizontalRect& light, const HorizontalRect& occluder,
                                      glm::dvec3 receiver) {
    const double lightHeight = light.centre.y - receiver.y;
    const double occluderHeight = occluder.centre.y - receiver.y;
    if (!(lightHeight > 0.0)) {
        throw std::invalid_argument("parallelRectOccluderVisibility: receiver not below the light");
    }
    const glm::dvec2 lightHalf = glm::abs(light.halfSize);
    const double lightArea = 4.0 * lightHalf.x * lightHalf.y;
    if (!(lightArea > 0.0)) {
        throw std::invalid_argument("parallelRectOccluderVisibility: empty light");
    }
    if (occluderHeight <= 0.0 || occluderHeight >= lightHeight) return 1.0;

    // The occluder seen from the receiver, projected onto the light's plane.
    const double scale = lightHeight / occluderHeight;
    const glm::dvec2 r{receiver.x, receiver.z};
    const glm::dvec2 centre = r + (glm::dvec2{occluder.centre.x, occluder.centre.z} - r) * scale;
    const glm::dvec2 half = glm::abs(occluder.halfSize) * scale;

    // Overlap of two axis-aligned rectangles.
    const glm::dvec2 lc{light.centre.x, light.centre.z};
    const glm::dvec2 lo = glm::max(lc - lightHalf, centre - half);
    const glm::dvec2 hi = glm::min(lc + lightHalf, centre + half);
    const double overlap = std::max(0.0, hi.x - lo.x) * std::max(0.0, hi.y - lo.y);
    return std::clamp(1.0 - overlap / lightArea, 0.0, 1.0);
}

double parallelSquareOccluderVisibility(glm::dvec3 lightCentre, double lightHalfSize,
                                        glm::dvec3 occluderCentre, double occluderHalfSize,
                                        glm::dvec3 receiver) {
    return parallelRectOccluderVisibility({lightCentre, glm::dvec2{lightHalfSize}},
                                          {occluderCentre, glm::dvec2{occluderHalfSize}}, receiver);
}

}  // namespace penumbra
