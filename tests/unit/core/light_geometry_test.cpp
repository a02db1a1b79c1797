// Light geometry: polygon/rect irradiance against closed forms and dense numerical integration,
// and the parallel-occluder visibility closed form against hand-computed cases and a grid count.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>
#include <vector>

#include <glm/geometric.hpp>

#include "renderer/core/light_geometry.h"

using glm::dvec3;
using penumbra::HorizontalRect;
using penumbra::parallelRectOccluderVisibility;
using penumbra::parallelSquareOccluderVisibility;
using penumbra::polygonFormFactorIrradiance;
using penumbra::rectLightIrradiance;

namespace {

// A rect light as renderer/scene/scene.h RectLight builds it, in double precision: corners
// counter-clockwise seen from the front, (-,-), (+,-), (+,+), (-,+) along right and upAxis.
struct Light {
    std::array<dvec3, 4> corners;
    dvec3 forward;
};

Light makeLight(dvec3 position, dvec3 target, dvec3 up, double width, double height) {
    const dvec3 forward = glm::normalize(target - position);
    const dvec3 right = glm::normalize(glm::cross(forward, up));
    const dvec3 upAxis = glm::cross(right, forward);
    const dvec3 r = right * (0.5 * width);
    const dvec3 u = upAxis * (0.5 * height);
    return {{position - r - u, position + r - u, position + r + u, position - r + u}, forward};
}

// Midpoint rule on an n x n grid over the light of
//   E = integral over the light of cos(theta_p) cos(theta_l) / r^2 dA
// with cos(theta_p) clamped at 0 (the receiver's horizon) and cos(theta_l) clamped at 0 (the
// light emits from its front face only): unit radiance, the same quantity rectLightIrradiance
// computes in closed form.
double integrateLight(const Light& light, dvec3 p, dvec3 n, int samples) {
    const dvec3 origin = light.corners[0];
    const dvec3 du = light.corners[1] - light.corners[0];
    const dvec3 dv = light.corners[3] - light.corners[0];
    const double dA = glm::length(glm::cross(du, dv)) / (double(samples) * samples);
    n = glm::normalize(n);
    double sum = 0.0;
    for (int i = 0; i < samples; ++i) {
        for (int j = 0; j < samples; ++j) {
            const dvec3 x = origin + du * ((i + 0.5) / samples) + dv * ((j + 0.5) / samples);
            const dvec3 w = x - p;
            const double r2 = glm::dot(w, w);
            const dvec3 dir = w / std::sqrt(r2);
            const double cosP = std::max(0.0, glm::dot(n, dir));
            const double cosL = std::max(0.0, -glm::dot(light.forward, dir));
            sum += cosP * cosL / r2;
        }
    }
    return sum * dA;
}

// Samples per side of the quadrature grid. The midpoint rule's error is O(h^2): for the smooth
// integrands here (receiver at least ~0.5 light sizes away) it is ~ (h / r)^2 / 24 times the
// integrand's relative curvature, ~1e-6 relative for h = size / 1000; where the horizon cuts the
// light the integrand has a kink along a line, whose cells add an error of the same order.
constexpr int kSamples = 1000;

// Relative tolerance against that quadrature: 1e-4 leaves two orders of margin over the ~1e-6
// quadrature error (measured: at most 9e-7 in the configurations here) while still catching any
// real mistake in the formula (a missed clip, a wrong edge sign or a lost edge is >= 1e-2).
constexpr double kQuadratureRel = 1e-4;
// Absolute floor for configurations whose irradiance is (nearly) zero, e.g. a thin sliver above
// the horizon: the kink error there scales with the light's size, not with the tiny result.
constexpr double kQuadratureAbs = 1e-7;

void expectMatchesQuadrature(const Light& light, dvec3 p, dvec3 n) {
    const double exact = rectLightIrradiance(light.corners, light.forward, p, n);
    const double numeric = integrateLight(light, p, n, kSamples);
    EXPECT_NEAR(exact, numeric, kQuadratureRel * numeric + kQuadratureAbs)
        << "p = (" << p.x << ", " << p.y << ", " << p.z << "), n = (" << n.x << ", " << n.y << ", "
        << n.z << ")";
}

// Unit-radiance irradiance at a receiver facing a parallel rectangle of sides a x b whose corner
// lies straight above it at distance c (pi times the classic form factor):
//   E = 1/2 [ a/sqrt(a^2+c^2) atan(b/sqrt(a^2+c^2)) + b/sqrt(b^2+c^2) atan(a/sqrt(b^2+c^2)) ].
double cornerRectIrradiance(double a, double b, double c) {
    const double ac = std::sqrt(a * a + c * c);
    const double bc = std::sqrt(b * b + c * c);
    return 0.5 * (a / ac * std::atan(b / ac) + b / bc * std::atan(a / bc));
}

// Any axis-aligned parallel rectangle [x0, x1] x [z0, z1] (relative to the receiver) at distance c,
// by inclusion-exclusion of signed corner rectangles.
double parallelRectIrradiance(double x0, double x1, double z0, double z1, double c) {
    auto signedCorner = [c](double x, double z) {
        const double s = (x < 0 ? -1.0 : 1.0) * (z < 0 ? -1.0 : 1.0);
        return s * cornerRectIrradiance(std::abs(x), std::abs(z), c);
    };
    return signedCorner(x1, z1) - signedCorner(x0, z1) - signedCorner(x1, z0) +
           signedCorner(x0, z0);
}

// Closed form against closed form: only rounding separates them (a few ulps per term, amplified
// by the cancellation of inclusion-exclusion for points outside the light's footprint).
constexpr double kClosedFormRel = 1e-10;

const dvec3 kUp{0, 1, 0};

}  // namespace

TEST(LightGeometry, SquareStraightAboveMatchesClosedForm) {
    // 1 x 1 light at height 1 facing down, receiver under its centre facing up.
    const Light light = makeLight({0, 1, 0}, {0, 0, 0}, {0, 0, -1}, 1.0, 1.0);
    const double expected = 4.0 * cornerRectIrradiance(0.5, 0.5, 1.0);
    EXPECT_NEAR(rectLightIrradiance(light.corners, light.forward, {0, 0, 0}, kUp), expected,
                kClosedFormRel * expected);
    expectMatchesQuadrature(light, {0, 0, 0}, kUp);
}

TEST(LightGeometry, RectangleAboveOffsetPointsMatchClosedForm) {
    // 1.5 (x) by 0.5 (z) light centred at (0.2, 2, -0.1); receivers inside and outside its
    // footprint, all facing up.
    const Light light = makeLight({0.2, 2, -0.1}, {0.2, 0, -0.1}, {0, 0, -1}, 1.5, 0.5);
    for (const dvec3 p : {dvec3{0, 0, 0}, dvec3{0.9, 0, 0.2}, dvec3{-1.5, 0, 0.4}, dvec3{3, 0, -2},
                          dvec3{0.2, 1.5, -0.1}}) {
        const double c = 2.0 - p.y;
        const double expected = parallelRectIrradiance(0.2 - 0.75 - p.x, 0.2 + 0.75 - p.x,
                                                       -0.1 - 0.25 - p.z, -0.1 + 0.25 - p.z, c);
        EXPECT_NEAR(rectLightIrradiance(light.corners, light.forward, p, kUp), expected,
                    kClosedFormRel * expected)
            << "p = (" << p.x << ", " << p.y << ", " << p.z << ")";
    }
}

TEST(LightGeometry, HugeCloseLightTendsToPi) {
    // A receiver 1 mm under the centre of a 100 m light sees the whole hemisphere covered:
    // E -> pi (unit radiance). The missing part is the solid angle beyond the light's edges,
    // of order c / half size = 2e-5 relative: allow 1e-4.
    const Light light = makeLight({0, 0.001, 0}, {0, 0, 0}, {0, 0, 1}, 100.0, 100.0);
    EXPECT_NEAR(rectLightIrradiance(light.corners, light.forward, {0, 0, 0}, kUp), std::numbers::pi,
                1e-4 * std::numbers::pi);
}

TEST(LightGeometry, TiltedLightMatchesQuadrature) {
    const Light light = makeLight({0.3, 1.5, -0.2}, {1.0, 0.0, 0.5}, {0, 1, 0}, 1.2, 0.7);
    expectMatchesQuadrature(light, {0, 0, 0}, kUp);
    expectMatchesQuadrature(light, {1.2, 0, 0.8}, kUp);
}

TEST(LightGeometry, OffsetLightMatchesQuadrature) {
    const Light light = makeLight({2.0, 1.0, 1.0}, {0, 0, 0}, {0, 1, 0}, 0.8, 0.8);
    expectMatchesQuadrature(light, {0, 0, 0}, kUp);
    expectMatchesQuadrature(light, {-0.5, 0, 0.3}, kUp);
}

TEST(LightGeometry, TiltedReceiverMatchesQuadrature) {
    const Light light = makeLight({0, 2, 0}, {0, 0, 0}, {0, 0, -1}, 1.0, 1.0);
    expectMatchesQuadrature(light, {0.3, 0, 0.1}, glm::normalize(dvec3{1, 1, 0.3}));
    expectMatchesQuadrature(light, {0, 0.5, 0}, glm::normalize(dvec3{-0.2, 1, 0.7}));
}

TEST(LightGeometry, LightPartlyBelowHorizonIsClipped) {
    const Light above = makeLight({0, 2, 0}, {0, 0, 0}, {0, 0, -1}, 1.0, 1.0);
    // A wall-like receiver under the light: the horizon splits the light in half along x ...
    expectMatchesQuadrature(above, {0, 0, 0}, {1, 0, 0});
    // ... diagonally ...
    expectMatchesQuadrature(above, {0, 1, 0}, glm::normalize(dvec3{1, 0.1, 1}));
    // ... and leaving only a sliver.
    expectMatchesQuadrature(above, {0, 1.5, 0}, glm::normalize(dvec3{1, 2.2, 0}));

    // A vertical light standing partly below a floor point's horizon (y = 0).
    const Light wall = makeLight({0, 0.2, -2}, {0, 0.2, 0}, {0, 1, 0}, 1.0, 1.0);
    expectMatchesQuadrature(wall, {0, 0, 0}, kUp);
    expectMatchesQuadrature(wall, {0.7, 0, -0.5}, kUp);

    // Clipping must matter here: the unclipped polygon sum would differ.
    const double clipped = rectLightIrradiance(above.corners, above.forward, {0, 0, 0}, {1, 0, 0});
    EXPECT_GT(clipped, 0.0);
    EXPECT_LT(clipped, rectLightIrradiance(above.corners, above.forward, {0, 0, 0}, kUp));
}

TEST(LightGeometry, LightFullyBelowHorizonGivesZero) {
    const Light light = makeLight({0, 2, 0}, {0, 0, 0}, {0, 0, -1}, 1.0, 1.0);
    EXPECT_EQ(rectLightIrradiance(light.corners, light.forward, {0, 0, 0}, {0, -1, 0}), 0.0);
    // Horizon plane exactly through the light's lowest edge: nothing strictly above it.
    const Light wall = makeLight({0, 0.5, -2}, {0, 0.5, 0}, {0, 1, 0}, 1.0, 1.0);
    EXPECT_NEAR(rectLightIrradiance(wall.corners, wall.forward, {0, 0, 0}, {0, -1, 0}), 0.0,
                1e-15);  // rounding only
}

TEST(LightGeometry, ReceiverBehindOrBesideLightGetsZero) {
    const Light light = makeLight({0, 2, 0}, {0, 0, 0}, {0, 0, -1}, 1.0, 1.0);
    // Above the downward-facing light, whichever way the receiver faces.
    EXPECT_EQ(rectLightIrradiance(light.corners, light.forward, {0, 3, 0}, {0, -1, 0}), 0.0);
    EXPECT_EQ(rectLightIrradiance(light.corners, light.forward, {0.2, 2.5, 0.3}, kUp), 0.0);
    // In the light's plane.
    EXPECT_EQ(rectLightIrradiance(light.corners, light.forward, {3, 2, 0}, {-1, 0, 0}), 0.0);
    // The same polygon as a two-sided polygon is seen from behind: non-zero.
    EXPECT_GT(polygonFormFactorIrradiance(light.corners, {0, 3, 0}, {0, -1, 0}), 0.0);
}

TEST(LightGeometry, FarAwayTendsToPointLightLimit) {
    // At distance r >> size, E -> A cos(theta_p) cos(theta_l) / r^2. The difference is of order
    // (size / r)^2 = 1e-4 relative here; allow 1e-3.
    const Light light = makeLight({30, 80, -40}, {0, 0, 0}, {0, 1, 0}, 1.0, 1.0);
    const dvec3 p{0.5, 0, 0.5};
    const dvec3 n = glm::normalize(dvec3{0.2, 1, 0});
    const dvec3 centre = dvec3{30, 80, -40};
    const dvec3 d = centre - p;
    const double r2 = glm::dot(d, d);
    const dvec3 dir = d / std::sqrt(r2);
    const double expected = 1.0 * glm::dot(n, dir) * -glm::dot(light.forward, dir) / r2;
    const double e = rectLightIrradiance(light.corners, light.forward, p, n);
    EXPECT_NEAR(e, expected, 1e-3 * expected);
    // Still exact against quadrature, despite the short edges (the cancellation-free edge term).
    expectMatchesQuadrature(light, p, n);
}

TEST(LightGeometry, RandomConfigurationsMatchQuadrature) {
    std::mt19937 rng(12345);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    std::uniform_real_distribution<double> size(0.2, 1.5);
    auto randomDir = [&] {
        for (;;) {
            const dvec3 v{unit(rng), unit(rng), unit(rng)};
            const double l = glm::length(v);
            if (l > 0.1 && l <= 1.0) return v / l;
        }
    };
    int lit = 0;
    for (int k = 0; k < 24; ++k) {
        const dvec3 position = dvec3{unit(rng), unit(rng), unit(rng)} * 2.0;
        const dvec3 forward = randomDir();
        const Light light =
            makeLight(position, position + forward, randomDir(), size(rng), size(rng));
        // Receivers at least 1 m from the light's centre keep the quadrature's error small.
        const dvec3 p = position + randomDir() * (1.0 + 1.5 * (unit(rng) + 1.0));
        const dvec3 n = randomDir();
        expectMatchesQuadrature(light, p, n);
        if (rectLightIrradiance(light.corners, light.forward, p, n) > 0.0) ++lit;
    }
    EXPECT_GE(lit, 6);  // the draw exercises lit receivers, not only zeros
}

TEST(LightGeometry, PolygonIsAdditiveAndWindingFree) {
    const Light light = makeLight({0.3, 1.5, -0.2}, {1.0, 0.0, 0.5}, {0, 1, 0}, 1.2, 0.7);
    const auto& c = light.corners;
    for (const dvec3 n : {kUp, dvec3{1, 0, 0}, glm::normalize(dvec3{1, 0.3, -1})}) {
        const dvec3 p{0, 0, 0};
        const double whole = polygonFormFactorIrradiance(c, p, n);
        const std::array<dvec3, 3> t0{c[0], c[1], c[2]};
        const std::array<dvec3, 3> t1{c[0], c[2], c[3]};
        const std::array<dvec3, 4> reversed{c[3], c[2], c[1], c[0]};
        // Exact identities of the formula: only rounding differs.
        EXPECT_NEAR(polygonFormFactorIrradiance(t0, p, n) + polygonFormFactorIrradiance(t1, p, n),
                    whole, 1e-12);
        EXPECT_NEAR(polygonFormFactorIrradiance(reversed, p, n), whole, 1e-12);
    }
    // Fewer than 3 vertices is no polygon.
    EXPECT_EQ(polygonFormFactorIrradiance(std::span<const dvec3>(c).first(2), {0, 0, 0}, kUp), 0.0);
}

// --- parallelSquareOccluderVisibility ---------------------------------------------------------

// The closed form is a ratio of rectangle areas: hand-computed cases hold to rounding.
constexpr double kAreaEps = 1e-12;

TEST(ParallelOccluderVisibility, Umbra) {
    // Light half size 0.5 at y = 2, occluder half size 0.5 at y = 1: seen from the origin the
    // occluder doubles to half size 1 and covers the whole light.
    EXPECT_NEAR(parallelSquareOccluderVisibility({0, 2, 0}, 0.5, {0, 1, 0}, 0.5, {0, 0, 0}), 0.0,
                kAreaEps);
}

TEST(ParallelOccluderVisibility, FullyLit) {
    EXPECT_NEAR(parallelSquareOccluderVisibility({0, 2, 0}, 0.5, {0, 1, 0}, 0.5, {5, 0, 0}), 1.0,
                kAreaEps);
    // Occluder above the light or below the receiver hides nothing.
    EXPECT_EQ(parallelSquareOccluderVisibility({0, 2, 0}, 0.5, {0, 3, 0}, 5.0, {0, 0, 0}), 1.0);
    EXPECT_EQ(parallelSquareOccluderVisibility({0, 2, 0}, 0.5, {0, -1, 0}, 5.0, {0, 0, 0}), 1.0);
}

TEST(ParallelOccluderVisibility, HalfCovered) {
    // Projected occluder: centre 2 * 0.5 = 1, half size 1, so it spans x in [0, 2] (z covers
    // all): the light's half x > 0 is hidden.
    EXPECT_NEAR(parallelSquareOccluderVisibility({0, 2, 0}, 0.5, {0.5, 1, 0}, 0.5, {0, 0, 0}), 0.5,
                kAreaEps);
}

TEST(ParallelOccluderVisibility, QuarterAndInteriorCover) {
    // Projected occluder spans [0, 2] in both x and z: one quadrant of the light hidden.
    EXPECT_NEAR(parallelSquareOccluderVisibility({0, 2, 0}, 0.5, {0.5, 1, 0.5}, 0.5, {0, 0, 0}),
                0.75, kAreaEps);
    // Small occluder: half size 0.1 doubles to 0.2, area 0.16 of the light's 1.
    EXPECT_NEAR(parallelSquareOccluderVisibility({0, 2, 0}, 0.5, {0, 1, 0}, 0.1, {0, 0, 0}), 0.84,
                kAreaEps);
    // Receiver not at y = 0: light 3 above, occluder 1 above, scale 3 about the receiver
    // (0.1, -1, 0): projected centre 0.1 + 3 * (0.2 - 0.1) = 0.4, half 0.3, x in [0.1, 0.7],
    // overlap with [-0.5, 0.5] is 0.4 wide and 0.6 deep: 0.24 of the light.
    EXPECT_NEAR(parallelSquareOccluderVisibility({0, 2, 0}, 0.5, {0.2, 0, 0}, 0.1, {0.1, -1, 0}),
                0.76, kAreaEps);
}

TEST(ParallelOccluderVisibility, Symmetric) {
    for (const double x : {0.1, 0.37, 0.8}) {
        for (const double z : {0.0, 0.25, -0.6}) {
            const double v =
                parallelSquareOccluderVisibility({0, 2, 0}, 0.5, {0, 1, 0}, 0.3, {x, 0, z});
            EXPECT_NEAR(
                v, parallelSquareOccluderVisibility({0, 2, 0}, 0.5, {0, 1, 0}, 0.3, {-x, 0, z}),
                kAreaEps);
            EXPECT_NEAR(v,
                        parallelSquareOccluderVisibility({0, 2, 0}, 0.5, {0, 1, 0}, 0.3, {z, 0, x}),
                        kAreaEps);
            EXPECT_GE(v, 0.0);
            EXPECT_LE(v, 1.0);
        }
    }
}

TEST(ParallelOccluderVisibility, RejectsReceiverNotBelowLight) {
    EXPECT_THROW(parallelSquareOccluderVisibility({0, 2, 0}, 0.5, {0, 1, 0}, 0.5, {0, 2, 0}),
                 std::invalid_argument);
}

TEST(ParallelOccluderVisibility, RectMatchesGridCount) {
    // Count, on an n x n grid of points over the light, the rays to the receiver that miss the
    // occluder. Each edge of the projected occluder that crosses the light misclassifies at most
    // one row (or column) of cells, so the count's error is at most 4 / n of the light's area for
    // these unit-ish rectangles: 1e-2 for n = 400.
    constexpr int n = 400;
    const HorizontalRect light{{0.1, 2.5, -0.2}, {0.6, 0.4}};
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int k = 0; k < 20; ++k) {
        const HorizontalRect occluder{{0.5 * u(rng), 1.4 + 0.5 * u(rng), 0.5 * u(rng)},
                                      {0.3 + 0.2 * u(rng), 0.3 + 0.2 * u(rng)}};
        const dvec3 receiver{u(rng), 0.3 * u(rng), u(rng)};
        int visible = 0;
        for (int i = 0; i < n; ++i) {
            for (int j = 0; j < n; ++j) {
                const dvec3 x{light.centre.x + light.halfSize.x * (2.0 * (i + 0.5) / n - 1.0),
                              light.centre.y,
                              light.centre.z + light.halfSize.y * (2.0 * (j + 0.5) / n - 1.0)};
                const double t = (occluder.centre.y - receiver.y) / (x.y - receiver.y);
                const dvec3 hit = receiver + (x - receiver) * t;
                const bool blocked = std::abs(hit.x - occluder.centre.x) < occluder.halfSize.x &&
                                     std::abs(hit.z - occluder.centre.z) < occluder.halfSize.y;
                if (!blocked) ++visible;
            }
        }
        EXPECT_NEAR(parallelRectOccluderVisibility(light, occluder, receiver),
                    double(visible) / (n * n), 4.0 / n);
    }
}
