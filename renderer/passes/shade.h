// The shade pass: beauty from the G-buffer, every light's exact unshadowed irradiance and its
// visibility layer; also the irradiance-weighted visibility PRODUCT.md defines. With a sample
// G-buffer (image.samples > 1) a second pass shades every sample of the pixels whose samples
// differ from the pixel's representative, each with the visibility of the pixel its depth
// matches best (Schwarz & Stamminger 2008, section 7), and averages them.
#pragma once

#include <map>
#include <vector>

#include "renderer/gl/dynamic_buffer.h"
#include "renderer/gl/handles.h"
#include "renderer/gl/program.h"
#include "renderer/passes/fullscreen.h"
#include "renderer/passes/gbuffer.h"
#include "renderer/passes/sample_gbuffer.h"
#include "renderer/scene/scene.h"

namespace penumbra::passes {

// Which pixel's visibility a sample that differs from its pixel's representative takes.
enum class SampleGuide {
    Depth,    // the 3 x 3 neighbour whose representative point lies nearest (the default)
    Nearest,  // its own pixel's (a baseline to measure the depth guidance against)
};

// Uploads LIGHTS into BUFFER as glsl/passes/shading.glsl's GpuLight array, bound at its
// binding.
void uploadGpuLights(gl::DynamicBuffer& buffer, const std::vector<scene::RectLight>& lights);

class Shade {
public:
    // SAMPLES > 1 also builds the multisampled programs (renderSamples()).
    // CASTER_FLAGS (GpuScene::casterFlags(), which must outlive this) says which objects cast:
    // beauty treats the horizon of those differently (glsl/passes/shading.glsl).
    Shade(int width, int height, int samples, const gl::Buffer& caster_flags);
    // One shading per pixel: the G-buffer point with its own visibility layers.
    // ENV_LAYER >= 0: the layer of VISIBILITY_LAYERS that holds the environment's irradiance
    // (shadowed rgb, unshadowed luminance in a), added to beauty.
    void render(const GBuffer& gbuffer, const gl::Texture& visibility_layers,
                const std::vector<scene::RectLight>& lights, int env_layer = -1);
    // After render(): marks the pixels where a sample of SAMPLES differs from the representative
    // (stencil), then shades and averages every sample of those pixels.
    void renderSamples(const GBuffer& gbuffer, const SampleGBuffer& samples,
                       const gl::Texture& visibility_layers,
                       const std::vector<scene::RectLight>& lights, int env_layer = -1);
    void setSampleGuide(SampleGuide guide) { guide_ = guide; }
    // Pixels the last renderSamples() shaded per sample (waits for the GPU).
    double samplePixels() const;
    const gl::Texture& beauty() const { return beauty_; }          // RGBA32F, a = coverage
    const gl::Texture& visibility() const { return visibility_; }  // R32F

private:
    // The program LABEL (FRAGMENT) for COUNT lights from CACHE, built on first use: the count
    // compiled in up to kCompiledLights (glsl/passes/shading.glsl, LIGHT_COUNT), else with the
    // count as a uniform (kept under the key -1).
    static constexpr int kCompiledLights = 8;
    const gl::Program& programFor(std::map<int, gl::Program>& cache, int count, const char* label,
                                  const char* fragment);

    int width_, height_, samples_;
    const gl::Buffer& caster_flags_;
    SampleGuide guide_ = SampleGuide::Depth;
    gl::Texture beauty_, visibility_, stencil_;
    gl::Framebuffer fbo_;
    std::map<int, gl::Program> programs_, samples_programs_;  // by light count (programFor)
    gl::Program classify_;                                    // for SAMPLES > 1
    gl::Query pixels_;                                        // samples passed, SAMPLES > 1
    gl::DynamicBuffer lights_{"lights"};
    Fullscreen fullscreen_;
};

}  // namespace penumbra::passes
