// Frame rendering: see frame_renderer.h.
#include "renderer/frame/frame_renderer.h"

#include <algorithm>

#include "renderer/core/error.h"
#include "renderer/frame/frame_image.h"
#include "renderer/gl/debug.h"

namespace penumbra::frame {

FrameRenderer::FrameRenderer(const gl::ContextInfo& gl, const scene::Scene& first,
                             const TechniqueInfo& info, const Params& params)
    : gl_(gl),
      info_(info),
      width_(first.image.width),
      height_(first.image.height),
      lights_(static_cast<int>(first.lights.size())),
      first_(first),
      gpu_(first),
      gbuffer_(width_, height_),
      sample_gbuffer_(first.image.samples > 1 ? std::make_unique<passes::SampleGBuffer>(
                                                    width_, height_, first.image.samples)
                                              : nullptr),
      shade_(width_, height_, first.image.samples, gpu_.casterFlags()) {
    setParams(params);
    gl::checkErrors("prepare");
}

void FrameRenderer::setParams(const Params& params) {
    if (technique_ && params.json() == params_.json()) return;
    params_ = params;
    technique_ = info_.create(params_);
    technique_->readInputs(first_);
    const int before = lights_;
    environment_ = {};
    if (first_.environment && info_.environment) environment_ = info_.environment(params_, first_);
    const int scene_lights = static_cast<int>(first_.lights.size());
    const int env_lights = static_cast<int>(environment_.lights.size());
    const bool fold = environment_.fold && env_lights > 0;
    lights_ = scene_lights + env_lights + (environment_.irradiance_layer && !fold ? 1 : 0);
    // Folded: the scene's lights, a batch of environment lights, the irradiance sum.
    const int layers_before = layers_;
    layers_ =
        fold ? scene_lights + std::min(env_lights, passes::EnvironmentFold::kBatch) + 1 : lights_;
    auto diagnostics = technique_->diagnostics();
    if (fold && !diagnostics.empty())
        throw RuntimeError(std::string(info_.name) + ": a folded environment has no diagnostics");
    // fold_ exists exactly while these parameters fold (render() asks only it).
    if (!fold)
        fold_.reset();
    else if (!fold_)
        fold_ = std::make_unique<passes::EnvironmentFold>(width_, height_, gpu_.casterFlags());
    if (!targets_ || diagnostics.size() != diagnostics_.size() || lights_ != before ||
        layers_ != layers_before)
        targets_ = std::make_unique<OutputTargets>(width_, height_, layers_,
                                                   static_cast<int>(diagnostics.size()));
    diagnostics_ = std::move(diagnostics);
    technique_->prepare(gl_, gpu_);
}

nlohmann::json FrameRenderer::render(const scene::Scene& s, gl::PassTimer& timer) {
    gpu_.update(s);
    const passes::CameraMatrices camera = passes::cameraMatrices(s.camera, width_, height_);
    nlohmann::json stats = nlohmann::json::object();
    for (const auto& [key, value] : environment_.stats.items()) stats[key] = value;
    all_lights_ = s.lights;
    all_lights_.insert(all_lights_.end(), environment_.lights.begin(), environment_.lights.end());
    FrameContext ctx(s, gpu_, gbuffer_, camera, *targets_, timer, stats);
    ctx.lights = all_lights_;
    ctx.pass("gbuffer", [&] { gbuffer_.render(gpu_, camera); });
    // Multisampling (section 7): the techniques see only the one-sample G-buffer above and
    // compute one visibility per pixel; the samples meet them in the shade pass.
    if (sample_gbuffer_) ctx.pass("gbuffer_msaa", [&] { sample_gbuffer_->render(gpu_, camera); });
    const int scene_lights = static_cast<int>(s.lights.size());
    const bool fold = fold_ != nullptr;
    if (fold) fold_->begin(all_lights_);
    const int batch = passes::EnvironmentFold::kBatch;
    for (int l = 0; l < lights_; ++l) {
        ctx.light = l;
        // A folded environment light: a layer of the batch (after the scene's); a full batch,
        // or the last, is added to the sum.
        const int e = l - scene_lights;
        ctx.layer = fold && e >= 0 ? scene_lights + e % batch : -1;
        technique_->render(ctx);
        if (ctx.layer >= 0 && (e % batch == batch - 1 || l == lights_ - 1)) {
            const int first = e - e % batch;
            ctx.pass("environment_fold", [&] {
                fold_->add(gbuffer_, targets_->visibility(), scene_lights, scene_lights + first,
                           e % batch + 1);
            });
        }
    }
    ctx.light = -1;
    ctx.layer = -1;
    if (fold)
        ctx.pass("environment_fold_end", [&] { fold_->end(targets_->visibility(), layers_ - 1); });
    const int env_layer = environment_.irradiance_layer || fold ? layers_ - 1 : -1;
    // Folded lights are in the environment's layer, not shaded again: only the scene's.
    const std::vector<scene::RectLight>& shaded = fold ? s.lights : all_lights_;
    ctx.pass("shade", [&] { shade_.render(gbuffer_, targets_->visibility(), shaded, env_layer); });
    if (sample_gbuffer_) {
        ctx.pass("shade_msaa", [&] {
            shade_.renderSamples(gbuffer_, *sample_gbuffer_, targets_->visibility(), shaded,
                                 env_layer);
        });
        // The pixels shaded per sample: where a sample shows another surface than the pixel.
        const double pixels = shade_.samplePixels();
        stats["msaa_pixels"] = pixels;
        stats["msaa_share"] = pixels / (double(width_) * double(height_));
    }
    return stats;
}

FrameReadback FrameRenderer::startReadback() {
    FrameReadback r = startFrameReadback(*readback_, gbuffer_, shade_, *targets_, layers_,
                                         static_cast<int>(first_.lights.size()),
                                         std::string(info_.name), diagnostics_);
    gl::checkErrors("readback");
    return r;
}

}  // namespace penumbra::frame
