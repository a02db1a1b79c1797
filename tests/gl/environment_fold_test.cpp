// The lights `reference` makes of an environment are folded a batch at a time into one
// irradiance layer (passes/environment_fold.h): the frame keeps a batch of layers for them, not
// one each, and beauty is what shading every light from its own layer gives.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "gl_test_env.h"
#include "renderer/techniques/environment_lights.h"
#include "renderer/techniques/technique.h"

using penumbra::testing::channel;

namespace {

penumbra::frame::RenderedFrame renderReference(const penumbra::scene::Scene& s) {
    const auto* technique = penumbra::techniques::findTechnique("reference");
    const penumbra::Params params =
        penumbra::resolveParams(technique->params, s.technique, "environment fold test");
    return penumbra::frame::renderFrame(penumbra::testing::glInfo(), s, *technique, params, {});
}

}  // namespace

// The same lights as scene lights, each shaded from its own layer (one map at its centre: N = 1,
// no jitter, as an environment light gets), against the folded environment: 61 lights, seven
// full batches and a last one of five.
TEST(EnvironmentFoldGL, BeautyEqualsEveryLightShadedFromItsOwnLayer) {
    const std::string block = R"({"name": "reference", "env_samples": 61, "map_size": 256,
                                  "samples": 1, "jitter": false})";
    auto source = penumbra::scene::SceneSource::load(
        std::string(PENUMBRA_SOURCE_DIR) + "/tests/data/gl/environment.json",
        {{"technique", block}});
    const penumbra::scene::Scene folded_scene = source.at(0);
    const auto* technique = penumbra::techniques::findTechnique("reference");
    const penumbra::Params params =
        penumbra::resolveParams(technique->params, folded_scene.technique, "test");
    const auto env = penumbra::techniques::sampledEnvironmentLights(params, folded_scene);
    ASSERT_TRUE(env.fold);
    ASSERT_EQ(env.lights.size(), 61u);
    penumbra::scene::Scene lights_scene = folded_scene;
    lights_scene.environment.reset();
    lights_scene.lights = env.lights;

    const auto folded = renderReference(folded_scene);
    const auto lit = renderReference(lights_scene);
    EXPECT_EQ(folded.stats.value("maps_rendered", 0), 61);
    EXPECT_EQ(lit.stats.value("maps_rendered", 0), 61);
    // Beauty: the same terms summed in another order (float rounding, stored as half).
    double worst = 0, sum = 0;
    long n = 0;
    for (const char* c : {"R", "G", "B"}) {
        const auto& a = channel(folded.image, c);
        const auto& b = channel(lit.image, c);
        for (size_t i = 0; i < a.size(); ++i) {
            worst = std::max(worst, std::fabs(double(a[i]) - b[i]) / std::max(1e-3, double(b[i])));
            sum += b[i];
            n += b[i] > 0;
        }
    }
    std::printf(
        "environment fold: beauty worst relative difference %.2e over %ld values, mean %.4f\n",
        worst, n, sum / std::max(1L, n));
    ASSERT_GT(n, 10000);
    EXPECT_LE(worst, 2e-3);  // half floats: 2^-11 relative, and the sums' rounding
    // Visibility: the same luminance-weighted shares (one sample a light: B = V where E > 0),
    // weighted by each light's E, which float gives to about 6e-4 relative for a light near the
    // horizon (IrradianceGL's worst: its edges' terms cancel), computed in two shaders that the
    // compiler orders differently: a few pixels move by up to about 1e-4.
    EXPECT_LE(penumbra::testing::maxAbsDifference(channel(folded.image, "visibility"),
                                                  channel(lit.image, "visibility")),
              2e-4);
}
