// The render targets of `ssm`: see targets.h.
#include "renderer/techniques/ssm/targets.h"

#include <string>

#include "renderer/core/error.h"

namespace penumbra::techniques::ssm {

DepthTarget::DepthTarget(int size, const char* label)
    : depth(gl::createTexture2D(GL_DEPTH_COMPONENT32F, size, size, label)),
      fbo(gl::createFramebuffer(label)) {
    glNamedFramebufferTexture(fbo.id(), GL_DEPTH_ATTACHMENT, depth.id(), 0);
    glNamedFramebufferDrawBuffer(fbo.id(), GL_NONE);
    glNamedFramebufferReadBuffer(fbo.id(), GL_NONE);
    if (glCheckNamedFramebufferStatus(fbo.id(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw RuntimeError(std::string("ssm: ") + label + ": framebuffer incomplete");
}

SoftShadowTarget::SoftShadowTarget(int size, GLenum format, const char* label)
    : occlusion(gl::createTexture2D(format, size, size, label)), fbo(gl::createFramebuffer(label)) {
    glTextureParameteri(occlusion.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(occlusion.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glNamedFramebufferTexture(fbo.id(), GL_COLOR_ATTACHMENT0, occlusion.id(), 0);
    if (glCheckNamedFramebufferStatus(fbo.id(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw RuntimeError(std::string("ssm: ") + label + ": framebuffer incomplete");
}

}  // namespace penumbra::techniques::ssm
