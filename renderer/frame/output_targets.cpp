// Output targets: see output_targets.h.
#include "renderer/frame/output_targets.h"

#include <algorithm>
#include <string>

#include "renderer/core/error.h"

namespace penumbra::frame {

OutputTargets::OutputTargets(int width, int height, int lights, int diagnostics)
    : width_(width),
      height_(height),
      visibility_(gl::createTexture2DArray(GL_RGBA32F, width, height, std::max(lights, 1),
                                           "visibility per light")),
      fbo_(gl::createFramebuffer("technique output")) {
    for (int i = 0; i < diagnostics; ++i)
        diagnostics_.push_back(gl::createTexture2DArray(GL_R32F, width, height, std::max(lights, 1),
                                                        "diagnostic " + std::to_string(i)));
    std::vector<GLenum> bufs;
    for (int i = 0; i <= diagnostics; ++i) bufs.push_back(GL_COLOR_ATTACHMENT0 + i);
    glNamedFramebufferDrawBuffers(fbo_.id(), static_cast<GLsizei>(bufs.size()), bufs.data());
}

GLuint OutputTargets::bind(int light) {
    glNamedFramebufferTextureLayer(fbo_.id(), GL_COLOR_ATTACHMENT0, visibility_.id(), 0, light);
    for (size_t i = 0; i < diagnostics_.size(); ++i)
        glNamedFramebufferTextureLayer(fbo_.id(), GL_COLOR_ATTACHMENT1 + static_cast<GLenum>(i),
                                       diagnostics_[i].id(), 0, light);
    if (glCheckNamedFramebufferStatus(fbo_.id(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw RuntimeError("technique output: framebuffer incomplete");
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
    glViewport(0, 0, width_, height_);
    return fbo_.id();
}

void OutputTargets::uploadVisibility(int light, std::span<const float> rgba) {
    if (rgba.size() != size_t(width_) * size_t(height_) * 4)
        throw RuntimeError("technique output: visibility upload of the wrong size");
    // Rows arrive top first, as readback gives them; GL's rows run bottom-up.
    const size_t row = size_t(width_) * 4;
    for (int y = 0; y < height_; ++y)
        glTextureSubImage3D(visibility_.id(), 0, 0, height_ - 1 - y, light, width_, 1, 1, GL_RGBA,
                            GL_FLOAT, rgba.data() + size_t(y) * row);
}

}  // namespace penumbra::frame
