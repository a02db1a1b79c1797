// `ssm`'s receiver layers built in one geometry pass (a k-buffer) against the depth peeling
// they replaced: the same layers where receivers stack, the passes each takes, the fallback.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "gl_test_env.h"
#include "glsl/techniques/ssm/bindings.glsl"
#include "renderer/passes/gpu_scene.h"
#include "renderer/passes/light_windows.h"
#include "renderer/techniques/ssm/receiver_layers.h"
#include "renderer/techniques/ssm/targets.h"

namespace {

using penumbra::passes::GpuScene;
using Build = penumbra::techniques::ssm::ReceiverLayers::Build;

struct Built {
    std::vector<float> depth;
    std::vector<int> ids;
    int used = 0, passes = 0;
};

penumbra::scene::Scene load(const std::string& path) {
    return penumbra::scene::SceneSource::load(std::string(PENUMBRA_SOURCE_DIR) + "/" + path, {})
        .at(0);
}

// The receiver layers of S's first light as `ssm` builds them (its windows and gap, a
// SIZE^2 map), read back.
Built build(const penumbra::scene::Scene& s, Build how, int layers, int size = 256) {
    namespace ssm = penumbra::techniques::ssm;
    penumbra::testing::glInfo();
    const GpuScene gpu(s);
    const auto& light = s.lights.at(0);
    std::vector<penumbra::passes::WorldBox> receivers;
    for (const auto& o : gpu.objects())
        if (penumbra::scene::receivesShadow(o.shadow)) receivers.push_back(o.world_box);
    const auto occ =
        ssm::withNearMargin(penumbra::passes::occluderWindow(light, gpu.casterBoxes()));
    const auto soft = ssm::softShadowWindow(light, occ, receivers);
    const penumbra::passes::LightDepthView view{soft.viewProj(light), soft.near,
                                                1.0f / (soft.far - soft.near)};
    ssm::ReceiverLayers r(size, layers, how, "test receiver layers");
    const auto result = r.render(gpu, GpuScene::Filter::Receivers, light, view,
                                 0.002f * soft.far / (soft.far - soft.near));
    Built b;
    b.used = result.used, b.passes = result.passes;
    const size_t n = size_t(size) * size_t(size) * size_t(layers);
    b.depth.resize(n);
    b.ids.resize(n);
    glGetTextureImage(r.depth.id(), 0, GL_DEPTH_COMPONENT, GL_FLOAT, GLsizei(n * 4),
                      b.depth.data());
    glGetTextureImage(r.ids.id(), 0, GL_RED_INTEGER, GL_INT, GLsizei(n * 4), b.ids.data());
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    return b;
}

// Expects A's layers equal to B's: the same ids, depths within the k-buffer's quantum.
void expectSameLayers(const Built& a, const Built& b, const std::string& what) {
    EXPECT_EQ(a.used, b.used) << what;
    long differing_ids = 0, differing_depths = 0, texels = 0;
    for (size_t i = 0; i < a.ids.size(); ++i) {
        texels += a.ids[i] >= 0;
        differing_ids += a.ids[i] != b.ids[i];
        differing_depths += std::fabs(a.depth[i] - b.depth[i]) > 1.0f / SSM_KBUFFER_DEPTH_STEPS;
    }
    std::printf("%s: %ld receiver texels over the layers, %ld ids and %ld depths differ\n",
                what.c_str(), texels, differing_ids, differing_depths);
    EXPECT_EQ(differing_ids, 0) << what;
    EXPECT_EQ(differing_depths, 0) << what;
}

}  // namespace

TEST(SsmReceiverLayersGL, OnePassEqualsPeelingWhereReceiversStack) {
    // under_table: the table top, the ball beneath it and the floor beneath both, three deep;
    // three_lights: boxes over a floor. Every layer count, since the last layer (the farthest)
    // and the spare slots change with it.
    for (const char* name : {"under_table", "three_lights"}) {
        const auto s = load(std::string("scenes/conformance/") + name + ".json");
        for (int layers : {1, 2, 3, 4, 8}) {
            const Built one = build(s, Build::KBuffer, layers);
            const Built peeled = build(s, Build::Peel, layers);
            expectSameLayers(one, peeled, std::string(name) + " layers " + std::to_string(layers));
            EXPECT_EQ(one.passes, 1);
            EXPECT_EQ(peeled.passes, std::min(peeled.used + 1, layers));
            if (layers >= 4 && std::string(name) == "under_table") {
                EXPECT_EQ(one.used, 3);
            }
        }
    }
}

TEST(SsmReceiverLayersGL, CrowdedTexelsFallBackToPeeling) {
    // Eight coincident boxes: eight surfaces at one depth fill the nearest slots of layers 4
    // (3 + 3 spares) before a second layer is found, so the frame is peeled after the
    // k-buffer pass, with the same result as peeling alone.
    const auto s = load("tests/data/gl/ssm_coincident_boxes.json");
    const Built one = build(s, Build::KBuffer, 4, 64);
    const Built peeled = build(s, Build::Peel, 4, 64);
    expectSameLayers(one, peeled, "coincident boxes");
    EXPECT_EQ(one.used, 2);  // the boxes' tops (the first box) and the floor
    EXPECT_EQ(one.passes, 1 + peeled.passes);
}

TEST(SsmReceiverLayersGL, TheFrameDrawsTheReceiversOnce) {
    nlohmann::json stats;
    penumbra::testing::renderScene("both_box.json", {{"image.width", "96"}, {"image.height", "72"}},
                                   0, &stats);
    EXPECT_EQ(stats.value("receiver_passes", -1), 1);
    EXPECT_EQ(stats.value("receiver_layers", -1), 2);
    // Scenes whose object ids do not fit the k-buffer's 12 bits are peeled.
    using penumbra::techniques::ssm::ReceiverLayers;
    EXPECT_EQ(ReceiverLayers::buildFor(SSM_KBUFFER_MAX_OBJECTS), Build::KBuffer);
    EXPECT_EQ(ReceiverLayers::buildFor(SSM_KBUFFER_MAX_OBJECTS + 1), Build::Peel);
}
