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

// Shadow-region MAE of the rendered visibility against the closed form, over floor pixels
// (id 0) where either is below 0.999 (Atty et al. 5.2.1).
double closedFormShadowMae(const penumbra::output::Image& img) {
    const auto& vis = channel(img, "visibility");
    const auto& id = channel(img, "id");
    const auto& px = channel(img, "P.X");
    const auto& py = channel(img, "P.Y");
    const auto& pz = channel(img, "P.Z");
    double sum = 0;
    long n = 0;
    for (size_t i = 0; i < vis.size(); ++i) {
        if (id[i] != 0.0f) continue;  // floor only
        // Scene: light 1x1 at y=3 centred on the origin; occluder 0.8x0.8 at (0.2, 1.5, 0.1).
        double expected = penumbra::parallelSquareOccluderVisibility(
            {0, 3, 0}, 0.5, {0.2, 1.5, 0.1}, 0.4, {px[i], py[i], pz[i]});
        if (expected >= 0.999 && vis[i] >= 0.999) continue;
        sum += std::fabs(expected - vis[i]);
        ++n;
    }
    EXPECT_GT(n, 1000) << "the shadow should cover a good part of the image";
    const double mae = n ? sum / static_cast<double>(n) : 1.0;
    std::printf("closed form: shadow-region MAE %.5f over %ld pixels\n", mae, n);
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
