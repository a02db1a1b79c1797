// The shade pass's unshadowed irradiance (GLSL, float) against the exact polygon form factor
// (C++, double): a scene without casters, so beauty = albedo/pi * L * E at every pixel, with
// receivers that see the light whole, clipped by their horizon, and not at all.
#include <gtest/gtest.h>

#include <cmath>

#include "gl_test_env.h"
#include "renderer/core/light_geometry.h"
#include "renderer/scene/scene_source.h"

using penumbra::testing::channel;
using penumbra::testing::renderScene;

TEST(IrradianceGL, ShadeMatchesExactFormFactor) {
    auto img = renderScene("irradiance.json", {});
    auto source = penumbra::scene::SceneSource::load(
        std::string(PENUMBRA_SOURCE_DIR) + "/tests/data/gl/irradiance.json", {});
    const auto light = source.at(0).lights.at(0);
    const auto c = light.corners();
    const std::array<glm::dvec3, 4> corners = {glm::dvec3(c[0]), glm::dvec3(c[1]), glm::dvec3(c[2]),
                                               glm::dvec3(c[3])};
    const double radiance_r = light.color.r * light.intensity;
    const auto& r = channel(img, "R");
    const auto& vis = channel(img, "visibility");
    const auto& id = channel(img, "id");
    const auto& px = channel(img, "P.X");
    const auto& py = channel(img, "P.Y");
    const auto& pz = channel(img, "P.Z");
    const auto& nx = channel(img, "N.X");
    const auto& ny = channel(img, "N.Y");
    const auto& nz = channel(img, "N.Z");
    long checked = 0, clipped = 0, dark = 0;
    double worst = 0;
    for (size_t i = 0; i < r.size(); ++i) {
        if (id[i] < 0) continue;
        EXPECT_EQ(vis[i], 1.0f) << "no casters: everything is lit";
        glm::dvec3 p(px[i], py[i], pz[i]);
        glm::dvec3 n = glm::normalize(glm::dvec3(nx[i], ny[i], nz[i]));
        double e = penumbra::rectLightIrradiance(corners, glm::dvec3(light.forward()), p, n);
        double expected = 1.0 / M_PI * radiance_r * e;  // white albedo
        int below = 0;
        for (const auto& k : corners) below += glm::dot(k - p, n) < 0;
        clipped += below > 0 && below < 4 && e > 0;
        dark += e == 0;
        // Relative 2e-3 + absolute 1e-4: float GLSL against double (2.4e-4 relative measured
        // offline), positions and normals stored as float, and edges (atan) in float.
        double err = std::fabs(r[i] - expected);
        worst = std::max(worst, err / (expected + 1e-3));
        EXPECT_LE(err, 2e-3 * expected + 1e-4) << "pixel " << i << " expected " << expected;
        ++checked;
    }
    EXPECT_GT(checked, 5000);
    EXPECT_GT(clipped, 200) << "the scene must exercise horizon clipping";
    EXPECT_GT(dark, 200) << "and points that see none of the light";
    std::printf("irradiance: %ld pixels, %ld clipped, %ld unlit, worst relative error %.2e\n",
                checked, clipped, dark, worst);
}
