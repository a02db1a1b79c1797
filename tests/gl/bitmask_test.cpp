// `bitmask` (Schwarz & Stamminger) on small scenes: accuracy against `reference` N = 32 on the
// default scene, classification without back-projection, budgets and their statistics, the
// acceleration structures and the area-accumulation alternative.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "gl_test_env.h"
#include "renderer/core/error.h"

using penumbra::testing::channel;
using penumbra::testing::renderScene;

namespace {

// The bitmask technique block with EXTRA keys (JSON members, comma-led).
std::string bitmask(const std::string& extra = "") {
    return R"({"name": "bitmask", "map_size": 256)" + extra + "}";
}

const std::vector<float>& truthOf(const std::string& scene) {
    static std::string cached_scene;
    static std::vector<float> cached;
    if (cached_scene != scene) {
        auto ref = renderScene(scene, {{"technique", R"({"name": "reference", "samples": 32,
                                                         "map_size": 512})"}});
        cached = channel(ref, "visibility");
        cached_scene = scene;
    }
    return cached;
}

struct Run {
    penumbra::output::Image image;
    nlohmann::json stats;
    double mae = 0;
};

Run run(const std::string& scene, const std::string& technique) {
    Run r;
    r.image = renderScene(scene, {{"technique", technique}}, 0, &r.stats);
    r.mae = penumbra::testing::shadowRegionMae(channel(r.image, "visibility"), truthOf(scene));
    return r;
}

}  // namespace

TEST(BitmaskGL, UnlimitedBudgetMatchesReferenceOnDefaultScene) {
    auto r = run("adaptive_default.json", bitmask(R"(, "budget": 0)"));
    std::printf(
        "bitmask unlimited, 256 bits, map 256, default scene: MAE %.5f; %.1f%% "
        "back-project, %.1f +- %.1f micro-occluders\n",
        r.mae, 100.0 * r.stats.value("backprojecting_share", 0.0),
        r.stats.value("micro_occluders_mean", 0.0), r.stats.value("micro_occluders_stddev", 0.0));
    // The issue's bound for unlimited budget and the 256-bit jittered bitmask.
    EXPECT_LE(r.mae, 0.03);
}
