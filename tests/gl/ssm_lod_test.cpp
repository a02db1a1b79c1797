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

TEST(SsmLodGL, MergesATiltedOccluderAsPlanes) {
    // ssm_tilted.json's square is turned 40 and 25 degrees from the light: its micro-patches'
    // depths step across every block, so depth-span merging (accumulate=area, as all merging
    // was before) merged 12 of 9148. With the light-sample masks a block merges where its
    // micro-patches lie near one plane, and the splat back-projects that plane's corners.
    // Measured at 128 x 128 maps: 9148 -> 595 patches, against lod 0 a mean difference of
    // 1.2e-4 and a max of 0.0067 (one sample in 150 at a penumbra edge: the plane has no gaps
    // between the micro-patches' steps).
    double full = 0.0, merged = 0.0, area = 0.0;
    const std::string maps = R"(, "map_size": 128, "ssm_size": 128)";
    const auto a = ssm("ssm_tilted.json", maps + R"(, "lod": 0)", &full);
    const auto b = ssm("ssm_tilted.json", maps, &merged);
    ssm("ssm_tilted.json", maps + R"(, "accumulate": "area")", &area);
    const auto& va = channel(a, "visibility");
    const auto& vb = channel(b, "visibility");
    double sum = 0.0;
    for (size_t i = 0; i < va.size(); ++i) sum += std::abs(va[i] - vb[i]);
    const double mean = sum / static_cast<double>(va.size()), max = maxAbsDifference(va, vb);
    std::printf(
        "ssm lod, tilted square: %.0f -> %.0f micro-patches (area: %.0f), mean "
        "difference %.2e, max %.2e\n",
        full, merged, area, mean, max);
    EXPECT_LT(merged * 10, full);
    EXPECT_GT(area * 10, 9 * full);  // the area sum's patches stay parallel to the light
    EXPECT_LE(mean, 5e-4);
    EXPECT_LE(max, 0.02);
}

TEST(SsmLodGL, KeepsTheSelfShadowOfACurvedCaster) {
    // lone_sphere.json: a sphere of role both under a 4 m light, its own surface a receiver
    // layer: merged patches of its cap shadow its lower half through the tangent-plane rule,
    // counted micro-patch by micro-patch (splat.frag), and the floor. Merged blocks are planes
    // through the sphere's micro-patches (within half of lod_depth x z), so the merged splat
    // must stay as close to `exact` as the full-detail one, on the sphere and on the floor.
    // Measured: 6416 -> 668 patches, sphere 0.0048 -> 0.0048, floor 0.114 -> 0.091 (the planes
    // leave no gaps between the micro-patches' steps; one-sided, the floor misses the far side).
    // Depth-span merging (before the planes): 4808 patches, the same image within 2.5e-4.
    double full = 0.0, merged = 0.0;
    // One-sided: the far hemisphere's map merges less and would blur the count.
    const std::string maps = R"(, "map_size": 128, "ssm_size": 128, "two_sided": false)";
    const auto exact = renderScene("lone_sphere.json", {});
    const auto a = ssm("lone_sphere.json", maps + R"(, "lod": 0)", &full);
    const auto b = ssm("lone_sphere.json", maps, &merged);
    const double sphere_full = penumbra::testing::objectShadowMae(exact, a, 1);
    const double sphere_merged = penumbra::testing::objectShadowMae(exact, b, 1);
    const double floor_full = penumbra::testing::floorShadowMae(exact, a);
    const double floor_merged = penumbra::testing::floorShadowMae(exact, b);
    std::printf(
        "ssm lod, sphere: %.0f -> %.0f micro-patches, shadow-region MAE against exact: "
        "sphere %.4f -> %.4f, floor %.4f -> %.4f\n",
        full, merged, sphere_full, sphere_merged, floor_full, floor_merged);
    EXPECT_LE(sphere_merged, sphere_full + 0.002);
    EXPECT_LE(floor_merged, floor_full + 0.002);
    EXPECT_LT(merged, 0.2 * full);
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
