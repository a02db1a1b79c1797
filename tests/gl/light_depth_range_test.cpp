// passes::LightDepthRangeTarget: the nearest and farthest caster depths of one blended draw
// equal, texel for texel, those of two depth-tested draws (LESS, and GREATER from a cleared 0).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "gl_test_env.h"
#include "renderer/passes/gpu_scene.h"
#include "renderer/passes/light_depth.h"
#include "renderer/passes/light_windows.h"

using namespace penumbra;

namespace {

std::vector<float> readR32F(const gl::Texture& t, int size, GLenum format) {
    std::vector<float> out(size_t(size) * size_t(size));
    glGetTextureImage(t.id(), 0, format, GL_FLOAT, GLsizei(out.size() * sizeof(float)), out.data());
    return out;
}

}  // namespace

TEST(LightDepthRangeGL, OneBlendedDrawEqualsTheTwoDepthTestedDraws) {
    penumbra::testing::glInfo();
    // Two balls of different sizes over a floor (only the balls cast): thick casters that
    // overlap as seen from the light.
    const scene::Scene s =
        scene::SceneSource::load(
            std::string(PENUMBRA_SOURCE_DIR) + "/scenes/conformance/spheres_three_sizes.json", {})
            .at(0);
    const passes::GpuScene gpu(s);
    const scene::RectLight& light = s.lights.at(0);
    const passes::LightWindow w = passes::windowOf(light, gpu.casterBoxes());
    ASSERT_FALSE(w.empty());
    const passes::LightDepthView view{w.viewProj(light), w.near, 1.0f / (w.far - w.near)};
    const int size = 256;
    const auto filter = passes::GpuScene::Filter::Casters;

    passes::LightDepthPass range_pass("test range", passes::LightDepthPass::Output::Range);
    passes::LightDepthRangeTarget range(size, "test range");
    range.render(gpu, range_pass, filter, light, view);
    passes::LightDepthPass depth_pass("test depth", passes::LightDepthPass::Output::Depth);
    passes::LightDepthTarget nearest(size, "test nearest"), farthest(size, "test farthest");
    nearest.render(gpu, depth_pass, filter, light, view, false);
    farthest.render(gpu, depth_pass, filter, light, view, true);

    const auto got_near = readR32F(range.nearest, size, GL_RED);
    const auto got_far = readR32F(range.farthest, size, GL_RED);
    const auto want_near = readR32F(nearest.depth, size, GL_DEPTH_COMPONENT);
    const auto want_far = readR32F(farthest.depth, size, GL_DEPTH_COMPONENT);
    long covered = 0, thick = 0, differ = 0;
    for (size_t i = 0; i < got_near.size(); ++i) {
        differ += got_near[i] != want_near[i] || got_far[i] != want_far[i];
        covered += got_near[i] < 1.0f;
        thick += got_far[i] > got_near[i] + 0.01f;
    }
    EXPECT_EQ(differ, 0);
    EXPECT_GT(covered, size * size / 50);  // the casters are in the map
    EXPECT_GT(thick, covered / 2);         // and their far sides lie well behind
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}
