// `hard`: one shadow map from the light's centre, with an optional PCF kernel.
#include <array>

#include "renderer/techniques/light_sampling.h"
#include "renderer/techniques/param_keys.h"
#include "renderer/techniques/registry_entries.h"

namespace penumbra::techniques {
namespace {

constexpr std::array kHardParams = {
    mapSizeParam(2048),
    intParam(kPcf, 1, 1, 15, "PCF kernel width in texels (1 = a single hard test)"),
    kNormalOffsetParam,
    kDepthBiasParam,
};

class Hard final : public Technique {
public:
    explicit Hard(const Params& p) : settings_(samplingSettings(p)) {
        settings_.test.pcf = p.get(kPcf);
        settings_.batch = 1;
    }
    void prepare(const gl::ContextInfo& gl, const passes::GpuScene&) override {
        sampler_.prepare(gl, settings_);
    }
    void render(frame::FrameContext& ctx) override {
        const LightSample centre{{0.5f, 0.5f}, 1.0f};
        int maps = sampler_.render(ctx, std::span(&centre, 1));
        ctx.stats["maps_rendered"] = ctx.stats.value("maps_rendered", 0) + maps;
    }

private:
    SamplingSettings settings_;
    LightSampler sampler_;
};

}  // namespace

const TechniqueInfo kHardTechnique = {
    "hard",
    "one shadow map from the light's centre (optional PCF): the hard-shadow baseline",
    kHardParams,
    [](const Params& p) -> std::unique_ptr<Technique> { return std::make_unique<Hard>(p); },
    nullptr,
    [](const Params& p, std::uint64_t) { return MemoryTerms{shadowMapArrayTerm(p, 1)}; }};

}  // namespace penumbra::techniques
