// `reference` and `hard` on small scenes: the closed form of a square occluder parallel to a
// square light above a plane, and hard == reference with one sample at the light's centre.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "gl_test_env.h"
#include "renderer/core/light_geometry.h"

using penumbra::testing::channel;
using penumbra::testing::renderScene;

namespace {

// The closed-form shadow-region MAE, printed.
double closedFormShadowMae(const penumbra::output::Image& img) {
    const double mae = penumbra::testing::closedFormShadowMae(img, 0.5, 1000);
    std::printf("closed form: shadow-region MAE %.5f\n", mae);
    return mae;
}

}  // namespace

TEST(ReferenceGL, MatchesClosedFormSquareOccluder) {
    auto img = renderScene("closed_form.json", {});
    // Tolerance 0.01 (the issue's bound): 16 x 16 stratified samples quantise visibility in
    // steps of 1/256 and jitter adds noise of the same order; 1024^2 maps add < 1 texel.
    EXPECT_LE(closedFormShadowMae(img), 0.01);
}

TEST(ReferenceGL, ErrorFallsWithSampleCount) {
    double coarse =
        closedFormShadowMae(renderScene("closed_form.json", {{"technique.samples", "3"}}));
    double fine =
        closedFormShadowMae(renderScene("closed_form.json", {{"technique.samples", "12"}}));
    EXPECT_LT(fine, coarse);
}

TEST(ReferenceGL, BatchSizeDoesNotChangeTheImage) {
    // Batching is a memory/pass-count trade only: 256 maps in 1 batch or in 37 must agree.
    auto a = renderScene("closed_form.json", {{"technique.batch", "256"}});
    auto b = renderScene("closed_form.json", {{"technique.batch", "7"}});
    const auto& va = channel(a, "visibility");
    const auto& vb = channel(b, "visibility");
    const double max = penumbra::testing::maxAbsDifference(va, vb);
    // Float sums in a different order: a few ulps of 1.
    EXPECT_LE(max, 1e-5);
}

TEST(HardGL, EqualsReferenceWithOneCentredSample) {
    auto hard =
        renderScene("closed_form.json", {{"technique", R"({"name": "hard", "map_size": 1024})"}});
    auto ref = renderScene("closed_form.json",
                           {{"technique.samples", "1"}, {"technique.jitter", "false"}});
    const auto& vh = channel(hard, "visibility");
    const auto& vr = channel(ref, "visibility");
    ASSERT_EQ(vh.size(), vr.size());
    long differ = 0;
    for (size_t i = 0; i < vh.size(); ++i) differ += vh[i] != vr[i];
    EXPECT_EQ(differ, 0);  // the same map, the same test: bit-identical
}

TEST(HardGL, PcfSoftensOnlyTheEdge) {
    auto sharp =
        renderScene("closed_form.json", {{"technique", R"({"name": "hard", "map_size": 256})"}});
    auto soft = renderScene("closed_form.json",
                            {{"technique", R"({"name": "hard", "map_size": 256, "pcf": 5})"}});
    const auto& vs = channel(sharp, "visibility");
    const auto& vp = channel(soft, "visibility");
    long partial_sharp = 0, partial_soft = 0;
    for (size_t i = 0; i < vs.size(); ++i) {
        partial_sharp += vs[i] > 0.01f && vs[i] < 0.99f;
        partial_soft += vp[i] > 0.01f && vp[i] < 0.99f;
    }
    EXPECT_EQ(partial_sharp, 0);  // one hard test per pixel: 0 or 1
    EXPECT_GT(partial_soft, 50);
}
