// Shared by `hard` and `reference`: shadow maps from sample points on the light, rendered in
// batches into a texture array and averaged with their weights into the visibility target.
#pragma once

#include <memory>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "renderer/core/memory_term.h"
#include "renderer/core/params.h"
#include "renderer/frame/frame_context.h"
#include "renderer/gl/context.h"
#include "renderer/passes/shadow_maps.h"
#include "renderer/techniques/param_keys.h"

namespace penumbra::techniques {

struct LightSample {
    glm::vec2 uv;  // position on the light in [0,1]^2 (0.5, 0.5 = centre)
    float weight;  // weights of one light sum to 1
};

// The settings that every shadow-map-sampling technique exposes.
struct SamplingSettings {
    int map_size = 1024;
    int batch = 32;  // maps per texture-array batch
    passes::ShadowTestSettings test;
};

class LightSampler {
public:
    void prepare(const gl::ContextInfo& gl, const SamplingSettings& settings);
    // Renders VISIBILITY = sum_k w_k lit_k for SAMPLES of ctx's light into ctx's output, one
    // "shadow_maps[b]" and one "shadow_test[b]" pass per batch. Returns maps rendered.
    int render(frame::FrameContext& ctx, std::span<const LightSample> samples);

private:
    SamplingSettings settings_;
    std::unique_ptr<passes::ShadowMapBatch> batch_;
    std::unique_ptr<passes::ShadowAccumulate> accumulate_;
    passes::SampleViewBuffer views_buffer_;
    std::vector<passes::SampleView> views_;
};

// The parameter rows every shadow-map-sampling technique shares (hard, reference).
constexpr ParamSpec mapSizeParam(int def) {
    return intParam(kMapSize, def, 16, 16384, "shadow map width and height in texels")
        .limitedBy(GlLimit::MaxTextureSize);
}
constexpr ParamSpec kNormalOffsetParam =
    floatParam(kNormalOffset, 1.5, 0.0, 16.0,
               "offset of a receiver that casts along its normal, in shadow-map texels "
               "(against acne; one that casts no shadow is tested where it is)");
constexpr ParamSpec kDepthBiasParam =
    floatParam(kDepthBias, 0.0005, 0.0, 0.1,
               "constant bias subtracted from receiver depth, in units of the caster depth range");

// Settings from the shared rows above.
SamplingSettings samplingSettings(const Params& params);

// The memory term of a LAYERS-deep array of PARAMS' map_size depth maps (32-bit).
MemoryTerm shadowMapArrayTerm(const Params& params, int layers);

}  // namespace penumbra::techniques
