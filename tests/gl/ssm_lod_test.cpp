// `ssm`'s micro-patch level of detail (`lod`, lod.comp): merged micro-patches keep the image of
// the full-detail splat, and both patch paths still give the same bytes.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include <nlohmann/json.hpp>

#include "gl_test_env.h"

using penumbra::testing::channel;
using penumbra::testing::maxAbsDifference;
using penumbra::testing::renderScene;

namespace {

// SCENE rendered by ssm with the technique keys EXTRA (JSON members, comma-led) and OVERRIDES;
// the micro-patch count into PATCHES.
penumbra::output::Image ssm(const std::string& scene, const std::string& extra, double* patches,
                            std::vector<penumbra::scene::Override> overrides = {}) {
    nlohmann::json stats;
    overrides.push_back({"technique", R"({"name": "ssm")" + extra + "}"});
    auto img = renderScene(scene, overrides, 0, &stats);
    if (patches) *patches = stats.value("micro_patches", 0.0);
    return img;
}

}  // namespace

TEST(SsmLodGL, MergesAFlatOccluderWithoutChangingTheImage) {
    // closed_form.json's square is parallel to the light: every micro-patch lies at one depth,
    // so 2^L x 2^L of them are exactly one patch of 2^L times the width (the covered area is a
    // product of interval lengths, additive over adjacent intervals). Only rounding differs:
    // 1.1e-4 measured at 256 x 256 maps; a merged patch drawn at the wrong size or place would
    // move the penumbra by a texel, tenths of visibility.
    double full = 0.0, merged = 0.0;
    const std::string maps = R"(, "map_size": 128, "ssm_size": 128)";
    const auto a = ssm("closed_form.json", maps + R"(, "lod": 0)", &full);
    const auto b = ssm("closed_form.json", maps, &merged);
    const double max = maxAbsDifference(channel(a, "visibility"), channel(b, "visibility"));
    std::printf("ssm lod, flat square: %.0f -> %.0f micro-patches, max difference %.2e\n", full,
                merged, max);
    EXPECT_LE(max, 1e-3);
    EXPECT_LT(merged * 16, full);  // the quads grow by far more than the square: levels >= 2
}

TEST(SsmLodGL, KeepsTheSelfShadowOfACurvedCaster) {
    // lone_sphere.json: a sphere of role both under a 4 m light, its own surface a receiver
    // layer: merged patches of its cap shadow its lower half through the tangent-plane rule,
    // counted micro-patch by micro-patch (splat.frag), and the floor. A merged patch's depth
    // differs from its micro-patches' by at most half of lod_depth x z. Measured at 128 x 128
    // maps, against lod 0: lod_depth 0.005 (the default) mean 1.7e-6, max 8e-5; 0.01 mean
    // 4.6e-5, max 0.013; 0.02, merging too much, mean 1.0e-3, max 0.09. The bounds sit between.
    double full = 0.0, merged = 0.0;
    // One-sided: the far hemisphere's map merges less and would blur the count.
    const std::string maps = R"(, "map_size": 128, "ssm_size": 128, "two_sided": false)";
    const auto a = ssm("lone_sphere.json", maps + R"(, "lod": 0)", &full);
    const auto b = ssm("lone_sphere.json", maps, &merged);
    const auto& va = channel(a, "visibility");
    const auto& vb = channel(b, "visibility");
    double sum = 0.0;
    for (size_t i = 0; i < va.size(); ++i) sum += std::abs(va[i] - vb[i]);
    const double mean = sum / static_cast<double>(va.size()), max = maxAbsDifference(va, vb);
    std::printf("ssm lod, sphere: %.0f -> %.0f micro-patches, mean difference %.2e, max %.2e\n",
                full, merged, mean, max);
    // accumulate=samples: a merged patch's edges and its micro-patches' (each sealed toward
    // its neighbours, at their own depths) put a few samples (1/256 each) on either side of an
    // edge differently; measured mean 1.6e-4, max 0.011 (the sum's: within 1e-4 and 0.01).
    EXPECT_LE(mean, 2.5e-4);
    EXPECT_LE(max, 0.015);
    EXPECT_LT(merged, 0.8 * full);  // 6416 -> 4808 measured
}

TEST(SsmLodGL, CpuPathEqualsGpuPathWithMergedPatches) {
    // Both paths list lod.comp's map of merged patches, in row-major order (compact.comp or the
    // host's readback), so the splats sum the same terms in the same order: equal bits.
    for (const char* scene : {"closed_form.json", "lone_sphere.json"}) {
        auto with = [&](const char* path) {
            return ssm(
                scene,
                R"(, "map_size": 64, "ssm_size": 64, "path": ")" + std::string(path) + R"(")",
                nullptr);
        };
        const auto gpu = with("gpu"), cpu = with("cpu");
        for (const char* c : {"visibility", "R", "G", "B"})
            EXPECT_EQ(maxAbsDifference(channel(gpu, c), channel(cpu, c)), 0.0) << scene << " " << c;
    }
}
