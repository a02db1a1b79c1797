// The multisampled G-buffer (image.samples > 1): the G-buffer of every sample of every pixel,
// one array layer per sample, each rendered with the projection shifted by the sample's
// sub-pixel offset. The shade pass reads it next to the one-sample G-buffer the techniques use.
#pragma once

#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "renderer/gl/handles.h"
#include "renderer/gl/program.h"
#include "renderer/passes/gbuffer.h"
#include "renderer/passes/gpu_scene.h"

namespace penumbra::passes {

// Offsets in pixels from the pixel centre (x right, y up) of COUNT samples (1, 2, 4 or 8): the
// standard Direct3D 10.1 patterns (those of most GPUs' MSAA).
std::span<const glm::vec2> sampleOffsets(int count);

// PROJECTION shifted so that pixel centres see the scene at OFFSET pixels from them.
glm::mat4 jitteredProjection(const glm::mat4& projection, glm::vec2 offset, int width, int height);

class SampleGBuffer {
public:
    SampleGBuffer(int width, int height, int samples);
    void render(const GpuScene& scene, const CameraMatrices& camera);

    int samples() const { return samples_; }
    // Array textures, layer = sample; formats as GBuffer's.
    const gl::Texture& position() const { return position_; }
    const gl::Texture& normal() const { return normal_; }
    const gl::Texture& albedo() const { return albedo_; }
    const gl::Texture& id() const { return id_; }

private:
    int width_, height_, samples_;
    gl::Texture position_, normal_, albedo_, id_, depth_;
    std::vector<gl::Framebuffer> fbos_;  // one per sample
    GBufferPrograms programs_;
};

}  // namespace penumbra::passes
