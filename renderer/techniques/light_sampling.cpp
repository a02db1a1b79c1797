// Light-sample shadow maps averaged into visibility: see light_sampling.h.
#include "renderer/techniques/light_sampling.h"

#include <algorithm>
#include <cstdint>

#include "renderer/core/memory_limit.h"

namespace penumbra::techniques {

SamplingSettings samplingSettings(const Params& p) {
    SamplingSettings s;
    s.map_size = p.get(kMapSize);
    s.test.normal_offset = static_cast<float>(p.get(kNormalOffset));
    s.test.depth_bias = static_cast<float>(p.get(kDepthBias));
    return s;
}

MemoryTerm shadowMapArrayTerm(const Params& p, int layers) {
    const int map = p.get(kMapSize);
    const auto m = static_cast<std::uint64_t>(map);
    std::string what = layers == 1 ? "the shadow map (" + squareText(map) + ")"
                                   : "the shadow map array (" + squareText(map) + " x " +
                                         std::to_string(layers) + ")";
    return {"technique.map_size", std::move(what),
            saturatingProduct({m, m, 4, static_cast<std::uint64_t>(layers)}), true};
}

void LightSampler::prepare(const gl::ContextInfo& gl, const SamplingSettings& settings) {
    settings_ = settings;
    settings_.batch = std::clamp(settings_.batch, 1, std::max(gl.max_array_layers, 1));
    batch_ = std::make_unique<passes::ShadowMapBatch>(settings_.map_size, settings_.batch,
                                                      gl.has_vertex_layer);
    accumulate_ = std::make_unique<passes::ShadowAccumulate>();
}

int LightSampler::render(frame::FrameContext& ctx, std::span<const LightSample> samples) {
    const scene::RectLight& light = ctx.currentLight();
    const auto corners = light.corners();
    views_.clear();
    for (const auto& s : samples) {
        glm::vec3 p =
            corners[0] + (corners[1] - corners[0]) * s.uv.x + (corners[3] - corners[0]) * s.uv.y;
        views_.push_back(
            passes::makeSampleView(light, p, ctx.gpu.casterBoxes(), s.weight, settings_.map_size));
    }
    views_buffer_.upload(views_);
    ctx.bindOutput();
    const float zero[4] = {0, 0, 0, 0};
    glClearBufferfv(GL_COLOR, 0, zero);
    const int n = static_cast<int>(views_.size());
    for (int base = 0, b = 0; base < n; base += settings_.batch, ++b) {
        const int count = std::min(settings_.batch, n - base);
        ctx.pass("shadow_maps[" + std::to_string(b) + "]",
                 [&] { batch_->render(ctx.gpu, base, count); });
        ctx.pass("shadow_test[" + std::to_string(b) + "]", [&] {
            ctx.bindOutput();
            glEnable(GL_BLEND);
            glBlendEquation(GL_FUNC_ADD);
            glBlendFunc(GL_ONE, GL_ONE);
            accumulate_->render(ctx.gbuffer, *batch_, base, count, light, settings_.test,
                                ctx.gpu.casterFlags());
            glDisable(GL_BLEND);
        });
    }
    return n;
}

}  // namespace penumbra::techniques
