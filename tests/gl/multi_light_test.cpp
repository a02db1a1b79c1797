// Several lights: each light's visibility is rendered on its own, beauty sums L_i E_i V_i, and
// the visibility channel is the irradiance-weighted mean sum(E_i V_i) / sum(E_i) (PRODUCT.md).
#include <gtest/gtest.h>

#include <cmath>

#include "gl_test_env.h"

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
    // Luminance of beauty is proportional to sum_i lum(L_i) E_i V_i; with V = 1 it would be
    // the unshadowed value, so E_i V_i per light comes from each single-light beauty.
    auto lum = [](const penumbra::output::Image& img, size_t i) {
        return 0.2126 * channel(img, "R")[i] + 0.7152 * channel(img, "G")[i] +
               0.0722 * channel(img, "B")[i];
    };
    long mixed = 0;
    for (size_t i = 0; i < v.size(); ++i) {
        if (channel(both, "id")[i] != 0) continue;
        double ea_va = lum(only_a, i), eb_vb = lum(only_b, i);  // albedo/pi lum(L) E V each
        if (va[i] <= 0.0f || vb[i] <= 0.0f) continue;           // E from beauty / V needs V > 0
        double ea = ea_va / va[i], eb = eb_vb / vb[i];
        double expected = (ea_va + eb_vb) / (ea + eb);
        // 1e-4: float sums in the shade pass and the division by V above.
        EXPECT_NEAR(v[i], expected, 1e-4) << "pixel " << i;
        // Beauty adds up too (half-float rounding is not involved: images are float here).
        EXPECT_NEAR(lum(both, i), ea_va + eb_vb, 1e-4 * (ea_va + eb_vb) + 1e-6);
        mixed += std::fabs(va[i] - vb[i]) > 0.2f;
    }
    EXPECT_GT(mixed, 100) << "the two lights must shadow different pixels";
}
