// A cover pass and a full program under a stencil: see cover_stencil.h.
#include "renderer/passes/cover_stencil.h"

namespace penumbra::passes {

void drawCovered(const std::function<void()>& cover, const std::function<void()>& full) {
    const GLint one = 1;
    glClearBufferiv(GL_STENCIL, 0, &one);
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_ALWAYS, 0, 0xff);
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    cover();
    glStencilFunc(GL_EQUAL, 1, 0xff);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    full();
    glDisable(GL_STENCIL_TEST);
}

void CoverStencil::attach(GLuint framebuffer, int width, int height) {
    if (texture_.id() == 0 || width != width_ || height != height_) {
        texture_ = gl::createTexture2D(GL_DEPTH24_STENCIL8, width, height, label_);
        width_ = width;
        height_ = height;
    }
    glNamedFramebufferTexture(framebuffer, GL_DEPTH_STENCIL_ATTACHMENT, texture_.id(), 0);
}

void CoverStencil::detach(GLuint framebuffer) {
    glNamedFramebufferTexture(framebuffer, GL_DEPTH_STENCIL_ATTACHMENT, 0, 0);
}

}  // namespace penumbra::passes
