// Frame rendering: see frame_renderer.h.
#include "renderer/render/frame_renderer.h"

#include "renderer/gl/debug.h"
#include "renderer/render/frame_image.h"

namespace penumbra::render {

FrameRenderer::FrameRenderer(const gl::ContextInfo& gl, const scene::Scene& first,
                             const techniques::TechniqueInfo& info, const Params& params)
    : gl_(gl),
      info_(info),
      width_(first.image.width),
      height_(first.image.height),
      lights_(static_cast<int>(first.lights.size())),
      gpu_(first),
      gbuffer_(width_, height_),
      shade_(width_, height_) {
    setParams(params);
    gl::checkErrors("prepare");
}

void FrameRenderer::setParams(const Params& params) {
    if (technique_ && params.json() == params_.json()) return;
    params_ = params;
    technique_ = info_.create(params_);
    auto diagnostics = technique_->diagnostics();
    if (!targets_ || diagnostics.size() != diagnostics_.size())
        targets_ = std::make_unique<OutputTargets>(width_, height_, lights_,
                                                   static_cast<int>(diagnostics.size()));
    diagnostics_ = std::move(diagnostics);
    technique_->prepare(gl_, gpu_);
}

nlohmann::json FrameRenderer::render(const scene::Scene& s, PassTimer& timer) {
    gpu_.update(s);
    const passes::CameraMatrices camera = passes::cameraMatrices(s.camera, width_, height_);
    nlohmann::json stats = nlohmann::json::object();
    FrameContext ctx(s, gpu_, gbuffer_, camera, *targets_, timer, stats);
    ctx.pass("gbuffer", [&] { gbuffer_.render(gpu_, camera); });
    for (int l = 0; l < lights_; ++l) {
        ctx.light = l;
        technique_->render(ctx);
    }
    ctx.light = -1;
    ctx.pass("shade", [&] { shade_.render(gbuffer_, targets_->visibility(), s.lights); });
    return stats;
}

output::Image FrameRenderer::readImage() const {
    output::Image image =
        readFrameImage(gbuffer_, shade_, *targets_, lights_, std::string(info_.name), diagnostics_);
    gl::checkErrors("readback");
    return image;
}

}  // namespace penumbra::render
