// `bitmask`'s screen-sized intermediate maps: see loq_targets.h.
#include "renderer/techniques/bitmask/loq_targets.h"

#include "renderer/core/error.h"

namespace penumbra::techniques::bitmask {
namespace {
void checkComplete(const gl::Framebuffer& fbo) {
    if (glCheckNamedFramebufferStatus(fbo.id(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw RuntimeError("bitmask: LOQ targets: framebuffer incomplete");
}
}  // namespace

LoqTargets::LoqTargets(int width, int height)
    : width_(width),
      height_(height),
      area_(gl::createTexture2D(GL_RGBA32F, width, height, "bitmask search areas")),
      loq_{gl::createTexture2D(GL_RGBA32F, width, height, "bitmask loq map"),
           gl::createTexture2D(GL_RGBA32F, width, height, "bitmask loq map (filter)")},
      classify_fbo_(gl::createFramebuffer("bitmask classify")),
      loq_fbo_{gl::createFramebuffer("bitmask loq 0"), gl::createFramebuffer("bitmask loq 1")} {
    glNamedFramebufferTexture(classify_fbo_.id(), GL_COLOR_ATTACHMENT0, area_.id(), 0);
    glNamedFramebufferTexture(classify_fbo_.id(), GL_COLOR_ATTACHMENT1, loq_[0].id(), 0);
    const GLenum both[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    glNamedFramebufferDrawBuffers(classify_fbo_.id(), 2, both);
    checkComplete(classify_fbo_);
    for (int i = 0; i < 2; ++i) {
        glNamedFramebufferTexture(loq_fbo_[i].id(), GL_COLOR_ATTACHMENT0, loq_[i].id(), 0);
        checkComplete(loq_fbo_[i]);
    }
}

void LoqTargets::bindClassify() {
    glBindFramebuffer(GL_FRAMEBUFFER, classify_fbo_.id());
    glViewport(0, 0, width_, height_);
}

void LoqTargets::bindLoq(int i) {
    glBindFramebuffer(GL_FRAMEBUFFER, loq_fbo_[i].id());
    glViewport(0, 0, width_, height_);
}

}  // namespace penumbra::techniques::bitmask
