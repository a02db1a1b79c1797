// Several lights: each light's visibility is rendered on its own, beauty sums the lights' terms,
// and the visibility channel is the irradiance-weighted mean sum(E_i V_i) / sum(E_i) (PRODUCT.md).
#include <gtest/gtest.h>

#include <cmath>

#include "gl_test_env.h"
#include "renderer/scene/scene_source.h"

using penumbra::testing::channel;
using penumbra::testing::renderScene;

TEST(MultiLightGL, VisibilityIsIrradianceWeighted) {
    // Each light alone: removing the other by giving it no intensity keeps everything else.
    auto both = renderScene("two_lights.json", {});
    auto only_a = renderScene("two_lights.json", {{"lights.1.intensity", "0"}});
    auto only_b = renderScene("two_lights.json", {{"lights.0.intensity", "0"}});
    const auto& v = channel(both, "visibility");
    const auto& va = channel(only_a, "visibility");
    const auto& vb = channel(only_b, "visibility");
    const auto lights = penumbra::scene::SceneSource::load(
                            std::string(PENUMBRA_SOURCE_DIR) + "/tests/data/gl/two_lights.json", {})
                            .at(0)
                            .lights;
    // E_i of each light at a pixel, exact (double), times the luminance of its radiance.
    auto weighted_e = [&](size_t light, size_t i) {
        const glm::vec3 l = lights[light].radiance();
        return (0.2126 * l.r + 0.7152 * l.g + 0.0722 * l.b) *
               penumbra::testing::pixelIrradiance(lights[light], both, i);
    };
    auto lum = [](const penumbra::output::Image& img, size_t i) {
        return 0.2126 * channel(img, "R")[i] + 0.7152 * channel(img, "G")[i] +
               0.0722 * channel(img, "B")[i];
    };
    long mixed = 0;
    for (size_t i = 0; i < v.size(); ++i) {
        if (channel(both, "id")[i] != 0) continue;
        const double ea = weighted_e(0, i), eb = weighted_e(1, i);
        if (ea + eb <= 0) continue;
        const double expected = (ea * va[i] + eb * vb[i]) / (ea + eb);
        // 5e-4: the shade pass's E in float GLSL against double here (2.4e-4 relative measured
        // by the irradiance test) moves the weighted mean by at most that times |va - vb|, plus
        // half-float normals in the image.
        EXPECT_NEAR(v[i], expected, 5e-4) << "pixel " << i;
        // Beauty adds up (half-float rounding is not involved: images are float here).
        const double sum = lum(only_a, i) + lum(only_b, i);
        EXPECT_NEAR(lum(both, i), sum, 1e-4 * sum + 1e-6);
        mixed += std::fabs(va[i] - vb[i]) > 0.2f;
    }
    EXPECT_GT(mixed, 100) << "the two lights must shadow different pixels";
}

TEST(MultiLightGL, EachLightsVisibilityIsOneOnTheBackground) {
    // scenes/conformance/two_lights.json at 64 x 48: its top rows see no geometry. What a
    // technique leaves in a light's layer there differed (0 for `reference`, 1 for `exact`),
    // so the per-light channels of two techniques differed where nothing is; they are 1 there,
    // as `visibility` is.
    for (const char* technique : {"exact", "reference", "hard"}) {
        auto img = renderScene("../../../scenes/conformance/two_lights.json",
                               {{"image.width", "64"},
                                {"image.height", "48"},
                                {"technique", std::string(R"({"name": ")") + technique + "\"}"}});
        const auto& id = channel(img, "id");
        long background = 0;
        for (size_t i = 0; i < id.size(); ++i) {
            if (id[i] >= 0) continue;
            ++background;
            for (const char* c : {"visibility", "visibility.0", "visibility.1"})
                ASSERT_EQ(channel(img, c)[i], 1.0f) << technique << " " << c << " pixel " << i;
        }
        EXPECT_GT(background, 50) << technique;
    }
}
