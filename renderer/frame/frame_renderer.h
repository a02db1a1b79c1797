// Renders frames of one scene with one technique on the current GL context: the G-buffer (and
// with image.samples > 1 the sample G-buffer), the technique once per light, the shade pass;
// and reads the result back as an Image.
// Driven by renderFrame (render_frame.h), the one render sequence.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "renderer/core/params.h"
#include "renderer/frame/frame_context.h"
#include "renderer/frame/frame_image.h"
#include "renderer/frame/technique.h"
#include "renderer/gl/context.h"
#include "renderer/gl/pass_timer.h"
#include "renderer/output/image.h"
#include "renderer/passes/environment_fold.h"
#include "renderer/passes/gbuffer.h"
#include "renderer/passes/gpu_scene.h"
#include "renderer/passes/sample_gbuffer.h"
#include "renderer/passes/shade.h"

namespace penumbra::frame {

class FrameRenderer {
public:
    // Uploads FIRST's models and creates the technique INFO with PARAMS.
    FrameRenderer(const gl::ContextInfo& gl, const scene::Scene& first, const TechniqueInfo& info,
                  const Params& params);

    // Recreates the technique when PARAMS differ from the current ones.
    void setParams(const Params& params);
    // Renders SCENE (same objects as FIRST, animated values) with every pass timed by TIMER.
    // Returns the technique statistics of this render.
    nlohmann::json render(const scene::Scene& scene, gl::PassTimer& timer);
    // The last render's copies queued (pixel buffers), to be waited for and assembled into the
    // image of PRODUCT.md's channels later (frame_image.h). The renderer must outlive them.
    FrameReadback startReadback();

    const passes::GpuScene& gpuScene() const { return gpu_; }
    // Samples per pixel (the scene's image.samples).
    int samples() const { return sample_gbuffer_ ? sample_gbuffer_->samples() : 1; }
    // How samples that differ from their pixel's representative find their visibility.
    void setSampleGuide(passes::SampleGuide guide) { shade_.setSampleGuide(guide); }
    // Lights rendered per frame: the scene's and those made of its environment (with a fold,
    // more than the output layers).
    int lightCount() const { return lights_; }
    const Params& params() const { return params_; }
    const TechniqueInfo& technique() const { return info_; }

private:
    const gl::ContextInfo& gl_;
    const TechniqueInfo& info_;
    Params params_;
    int width_, height_, lights_;  // lights_: the scene's and the environment's
    int layers_ = 0;               // output layers (fewer than lights_ + 1 with a fold)
    const scene::Scene& first_;
    EnvironmentLights environment_;
    std::vector<scene::RectLight> all_lights_;
    passes::GpuScene gpu_;
    passes::GBuffer gbuffer_;
    std::unique_ptr<passes::SampleGBuffer> sample_gbuffer_;  // image.samples > 1 only
    passes::Shade shade_;
    std::unique_ptr<passes::EnvironmentFold> fold_;  // while the environment's lights fold
    std::unique_ptr<Technique> technique_;
    std::vector<DiagnosticChannel> diagnostics_;
    std::unique_ptr<OutputTargets> targets_;
    std::shared_ptr<passes::ReadbackPool> readback_ = passes::ReadbackPool::create();
};

}  // namespace penumbra::frame
