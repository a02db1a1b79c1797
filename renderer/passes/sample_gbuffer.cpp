// The multisampled G-buffer: see sample_gbuffer.h.
#include "renderer/passes/sample_gbuffer.h"

#include <array>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

#include "renderer/core/error.h"

namespace penumbra::passes {
namespace {
// Direct3D's standard sample positions, given there in 1/16 pixel with y running down.
glm::vec2 d3d(float x, float y) {
    return {x / 16.0f, -y / 16.0f};
}
const std::array<glm::vec2, 1> kOne = {d3d(0, 0)};
const std::array<glm::vec2, 2> kTwo = {d3d(4, 4), d3d(-4, -4)};
const std::array<glm::vec2, 4> kFour = {d3d(-2, -6), d3d(6, -2), d3d(-6, 2), d3d(2, 6)};
const std::array<glm::vec2, 8> kEight = {d3d(1, -3), d3d(-1, 3),  d3d(5, 1), d3d(-3, -5),
                                         d3d(-5, 5), d3d(-7, -1), d3d(3, 7), d3d(7, -7)};
}  // namespace

std::span<const glm::vec2> sampleOffsets(int count) {
    switch (count) {
        case 1:
            return kOne;
        case 2:
            return kTwo;
        case 4:
            return kFour;
        case 8:
            return kEight;
        default:
            throw RuntimeError("sample G-buffer: no pattern for " + std::to_string(count));
    }
}

glm::mat4 jitteredProjection(const glm::mat4& projection, glm::vec2 offset, int width, int height) {
    // A clip-space translation by t moves every point's NDC by t, so a pixel centre then sees
    // what lay -t from it: shift by minus the offset (in NDC, 2 / size per pixel).
    const glm::vec2 t = -2.0f * offset / glm::vec2(width, height);
    return glm::translate(glm::mat4(1.0f), glm::vec3(t, 0.0f)) * projection;
}

SampleGBuffer::SampleGBuffer(int width, int height, int samples)
    : width_(width),
      height_(height),
      samples_(samples),
      position_(
          gl::createTexture2DArray(GL_RGBA32F, width, height, samples, "sample gbuffer position")),
      normal_(
          gl::createTexture2DArray(GL_RGBA32F, width, height, samples, "sample gbuffer normal")),
      albedo_(
          gl::createTexture2DArray(GL_RGBA16F, width, height, samples, "sample gbuffer albedo")),
      id_(gl::createTexture2DArray(GL_R32I, width, height, samples, "sample gbuffer id")),
      depth_(gl::createTexture2DArray(GL_DEPTH_COMPONENT32F, width, height, samples,
                                      "sample gbuffer depth")),
      programs_(buildGBufferPrograms()) {
    sampleOffsets(samples);  // a count without a pattern fails here, not mid-frame
    for (int s = 0; s < samples; ++s) {
        gl::Framebuffer fbo = gl::createFramebuffer("sample gbuffer " + std::to_string(s));
        const GLuint f = fbo.id();
        glNamedFramebufferTextureLayer(f, GL_COLOR_ATTACHMENT0, position_.id(), 0, s);
        glNamedFramebufferTextureLayer(f, GL_COLOR_ATTACHMENT1, normal_.id(), 0, s);
        glNamedFramebufferTextureLayer(f, GL_COLOR_ATTACHMENT2, albedo_.id(), 0, s);
        glNamedFramebufferTextureLayer(f, GL_COLOR_ATTACHMENT3, id_.id(), 0, s);
        glNamedFramebufferTextureLayer(f, GL_DEPTH_ATTACHMENT, depth_.id(), 0, s);
        const GLenum bufs[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2,
                               GL_COLOR_ATTACHMENT3};
        glNamedFramebufferDrawBuffers(f, 4, bufs);
        if (glCheckNamedFramebufferStatus(f, GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
            throw RuntimeError("sample gbuffer: framebuffer incomplete");
        fbos_.push_back(std::move(fbo));
    }
}

void SampleGBuffer::render(const GpuScene& scene, const CameraMatrices& camera) {
    const auto offsets = sampleOffsets(samples_);
    for (int s = 0; s < samples_; ++s)
        drawGBuffer(fbos_[static_cast<size_t>(s)].id(), width_, height_, programs_, scene,
                    camera.view,
                    jitteredProjection(camera.projection, offsets[static_cast<size_t>(s)], width_,
                                       height_));
}

}  // namespace penumbra::passes
