// The render targets of `ssm`: see targets.h.
#include "renderer/techniques/ssm/targets.h"

#include <string>

#include "renderer/core/error.h"

namespace penumbra::techniques::ssm {

DepthTarget::DepthTarget(int size_, const char* label)
    : size(size_),
      depth(gl::createTexture2D(GL_DEPTH_COMPONENT32F, size_, size_, label)),
      fbo(gl::createFramebuffer(label)) {
    glNamedFramebufferTexture(fbo.id(), GL_DEPTH_ATTACHMENT, depth.id(), 0);
    glNamedFramebufferDrawBuffer(fbo.id(), GL_NONE);
    glNamedFramebufferReadBuffer(fbo.id(), GL_NONE);
    if (glCheckNamedFramebufferStatus(fbo.id(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw RuntimeError(std::string("ssm: ") + label + ": framebuffer incomplete");
}

void DepthTarget::render(const passes::GpuScene& scene, const gl::Program& program,
                         passes::GpuScene::Filter filter, const glm::mat4& view_proj,
                         const scene::RectLight& light, float near, float inv_range,
                         bool farthest) const {
    glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
    glViewport(0, 0, size, size);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(farthest ? GL_GREATER : GL_LESS);
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
    const float clear = farthest ? 0.0f : 1.0f;
    glClearNamedFramebufferfv(fbo.id(), GL_DEPTH, 0, &clear);
    glUseProgram(program.id());
    gl::setUniform(program, "u_view_proj", view_proj);
    gl::setUniform(program, "u_light_centre", light.position);
    gl::setUniform(program, "u_light_forward", light.forward());
    gl::setUniform(program, "u_near", near);
    gl::setUniform(program, "u_inv_range", inv_range);
    scene.draw(program, filter);
    glDepthFunc(GL_LESS);
    glDisable(GL_DEPTH_TEST);
    glUseProgram(0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
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
