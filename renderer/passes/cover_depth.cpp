// Draws that settle pixels in turn, under a depth test: see cover_depth.h.
#include "renderer/passes/cover_depth.h"

namespace penumbra::passes {

void drawInTurn(std::initializer_list<std::function<void()>> draws) {
    GLboolean write_mask = GL_TRUE;
    GLint func = GL_LESS;
    glGetBooleanv(GL_DEPTH_WRITEMASK, &write_mask);
    glGetIntegerv(GL_DEPTH_FUNC, &func);
    glDepthMask(GL_TRUE);  // also for the clear
    const float far = 1.0f;
    glClearBufferfv(GL_DEPTH, 0, &far);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    for (const auto& draw : draws) draw();
    glDisable(GL_DEPTH_TEST);
    glDepthFunc(static_cast<GLenum>(func));
    glDepthMask(write_mask);
}

void drawCovered(const std::function<void()>& cover, const std::function<void()>& full) {
    drawInTurn({cover, full});
}

void CoverDepth::attach(GLuint framebuffer, int width, int height) {
    if (texture_.id() == 0 || width != width_ || height != height_) {
        texture_ = gl::createTexture2D(GL_DEPTH_COMPONENT16, width, height, label_);
        width_ = width;
        height_ = height;
    }
    glNamedFramebufferTexture(framebuffer, GL_DEPTH_ATTACHMENT, texture_.id(), 0);
}

void CoverDepth::detach(GLuint framebuffer) {
    glNamedFramebufferTexture(framebuffer, GL_DEPTH_ATTACHMENT, 0, 0);
}

}  // namespace penumbra::passes
