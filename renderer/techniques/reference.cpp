// `reference`: N x N stratified, jittered samples on the light, one hard shadow map each,
// averaged: the papers' map-based baseline (`exact` is the ground truth). Maps are rendered in
// batches through a texture array, so memory stays bounded up to N = 32 (1024 maps).
#include <algorithm>
#include <array>
#include <cstdint>

#include "renderer/techniques/environment_lights.h"
#include "renderer/techniques/jitter_hash.h"
#include "renderer/techniques/light_sampling.h"
#include "renderer/techniques/param_keys.h"
#include "renderer/techniques/registry_entries.h"

namespace penumbra::techniques {
namespace {

constexpr IntKey kBatch{"batch"};

constexpr std::array kReferenceParams = joinParams(
    std::array{
        intParam(kSamples, 16, 1, 32, "N: the light is sampled on an N x N stratified grid"),
        boolParam(kJitter, true, "jitter each sample inside its stratum (false: stratum centres)"),
        intParam(kSeed, 1, 0, 1 << 30, "seed of the jitter pattern"),
        mapSizeParam(1024),
        intParam(kBatch, 32, 1, 256, "shadow maps per texture-array batch (memory vs. passes)"),
        kNormalOffsetParam,
        kDepthBiasParam,
    },
    kSampledEnvironmentParams);

class Reference final : public Technique {
public:
    explicit Reference(const Params& p)
        : n_(p.get(kSamples)),
          jitter_(p.get(kJitter)),
          seed_(static_cast<std::uint32_t>(p.get(kSeed))),
          settings_(samplingSettings(p)) {
        settings_.batch = p.get(kBatch);
        const float w = 1.0f / static_cast<float>(n_ * n_);
        for (int j = 0; j < n_; ++j)
            for (int i = 0; i < n_; ++i) {
                float jx =
                    jitter_ ? hashToUnit(seed_, std::uint32_t(i), std::uint32_t(2 * j)) : 0.5f;
                float jy =
                    jitter_ ? hashToUnit(seed_, std::uint32_t(i), std::uint32_t(2 * j + 1)) : 0.5f;
                samples_.push_back({{(float(i) + jx) / float(n_), (float(j) + jy) / float(n_)}, w});
            }
    }
    void prepare(const gl::ContextInfo& gl, const passes::GpuScene&) override {
        sampler_.prepare(gl, settings_);
    }
    void render(frame::FrameContext& ctx) override {
        // A light sampled from the environment is one direction: one map at its centre.
        const LightSample centre{{0.5f, 0.5f}, 1.0f};
        int maps = ctx.environmentLight() ? sampler_.render(ctx, std::span(&centre, 1))
                                          : sampler_.render(ctx, samples_);
        ctx.stats["maps_rendered"] = ctx.stats.value("maps_rendered", 0) + maps;
    }

private:
    int n_;
    bool jitter_;
    std::uint32_t seed_;
    SamplingSettings settings_;
    std::vector<LightSample> samples_;
    LightSampler sampler_;
};

}  // namespace

const TechniqueInfo kReferenceTechnique = {
    "reference",
    "N x N stratified jittered light samples, one shadow map each, averaged: the papers' baseline",
    kReferenceParams,
    [](const Params& p) -> std::unique_ptr<Technique> { return std::make_unique<Reference>(p); },
    sampledEnvironmentLights,
    [](const Params& p, std::uint64_t) {
        const int n = p.get(kSamples);
        return MemoryTerms{shadowMapArrayTerm(p, std::min(p.get(kBatch), n * n))};
    },
    nullptr,
    sampledEnvironmentLightsMax};

}  // namespace penumbra::techniques
