// The light depth pass: see light_depth.h.
#include "renderer/passes/light_depth.h"

#include <string>

#include "renderer/core/error.h"

namespace penumbra::passes {

void beginDepthMapDraw(GLuint fbo, int size) {
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glViewport(0, 0, size, size);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
}

void setLightFrameUniforms(const gl::Program& program, const scene::RectLight& light) {
    gl::setUniform(program, "u_light_centre", light.position);
    gl::setUniform(program, "u_light_right", light.right());
    gl::setUniform(program, "u_light_up", light.upAxis());
    gl::setUniform(program, "u_light_forward", light.forward());
}

void checkFramebuffer(const gl::Framebuffer& fbo, const char* label) {
    if (glCheckNamedFramebufferStatus(fbo.id(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw RuntimeError(std::string(label) + ": framebuffer incomplete");
}

gl::Program buildSampleDepthProgram(const char* label, bool vertex_layer) {
    return gl::buildProgram(label, {"passes/light_depth.vert", "passes/light_depth.frag"},
                            {{"SAMPLE_VIEWS", "1"}, {"VERTEX_LAYER", vertex_layer ? "1" : "0"}});
}

LightDepthPass::LightDepthPass(const char* label, Output output)
    : output_(output),
      program_(gl::buildProgram(
          label, {"passes/light_depth.vert", "passes/light_depth.frag"},
          {{"IDS", output == Output::DepthAndIds || output == Output::DistanceAndIds ? "1" : "0"},
           {"DISTANCE", output == Output::Distance || output == Output::DistanceAndIds ? "1" : "0"},
           {"RANGE", output == Output::Range ? "1" : "0"}})) {}

LightDepthPass::LightDepthPass(const char* label, const char* fragment, bool with_ids)
    : output_(Output::Depth),
      program_(gl::buildProgram(label, {"passes/light_depth.vert", fragment},
                                {{"PEEL", "1"}, {"IDS", with_ids ? "1" : "0"}})) {}

void LightDepthPass::draw(const GpuScene& scene, GpuScene::Filter filter,
                          const scene::RectLight& light, const LightDepthView& view) const {
    glUseProgram(program_.id());
    gl::setUniform(program_, "u_view_proj", view.view_proj);
    setLightFrameUniforms(program_, light);
    if (output_ != Output::Distance && output_ != Output::DistanceAndIds) {
        gl::setUniform(program_, "u_near", view.near);
        gl::setUniform(program_, "u_inv_range", view.inv_range);
    }
    scene.draw(program_, filter);
}

LightDepthTarget::LightDepthTarget(int size_, const char* label, bool with_ids)
    : size(size_),
      depth(gl::createTexture2D(GL_DEPTH_COMPONENT32F, size_, size_, label)),
      fbo(gl::createFramebuffer(label)) {
    glNamedFramebufferTexture(fbo.id(), GL_DEPTH_ATTACHMENT, depth.id(), 0);
    if (with_ids) {
        ids = gl::createTexture2D(GL_R32I, size_, size_, label);
        glNamedFramebufferTexture(fbo.id(), GL_COLOR_ATTACHMENT0, ids.id(), 0);
    }
    glNamedFramebufferDrawBuffer(fbo.id(), with_ids ? GL_COLOR_ATTACHMENT0 : GL_NONE);
    glNamedFramebufferReadBuffer(fbo.id(), GL_NONE);
    checkFramebuffer(fbo, label);
}

void LightDepthTarget::render(const GpuScene& scene, const LightDepthPass& pass,
                              GpuScene::Filter filter, const scene::RectLight& light,
                              const LightDepthView& view, bool farthest) const {
    beginDepthMapDraw(fbo.id(), size);
    glDepthFunc(farthest ? GL_GREATER : GL_LESS);
    const float clear = farthest ? 0.0f : 1.0f;
    glClearNamedFramebufferfv(fbo.id(), GL_DEPTH, 0, &clear);
    if (ids) {
        const GLint none = -1;
        glClearNamedFramebufferiv(fbo.id(), GL_COLOR, 0, &none);
    }
    pass.draw(scene, filter, light, view);
    glDepthFunc(GL_LESS);
    glDisable(GL_DEPTH_TEST);
    glUseProgram(0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

LightDepthRangeTarget::LightDepthRangeTarget(int size_, const char* label)
    : size(size_),
      nearest(gl::createTexture2D(GL_R32F, size_, size_, label)),
      farthest(gl::createTexture2D(GL_R32F, size_, size_, label)),
      fbo(gl::createFramebuffer(label)) {
    glNamedFramebufferTexture(fbo.id(), GL_COLOR_ATTACHMENT0, nearest.id(), 0);
    glNamedFramebufferTexture(fbo.id(), GL_COLOR_ATTACHMENT1, farthest.id(), 0);
    const GLenum buffers[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    glNamedFramebufferDrawBuffers(fbo.id(), 2, buffers);
    glNamedFramebufferReadBuffer(fbo.id(), GL_NONE);
    checkFramebuffer(fbo, label);
}

void LightDepthRangeTarget::render(const GpuScene& scene, const LightDepthPass& pass,
                                   GpuScene::Filter filter, const scene::RectLight& light,
                                   const LightDepthView& view) const {
    beginDepthMapDraw(fbo.id(), size);
    glDisable(GL_DEPTH_TEST);
    const float none_near[4] = {1, 0, 0, 0}, none_far[4] = {0, 0, 0, 0};
    glClearNamedFramebufferfv(fbo.id(), GL_COLOR, 0, none_near);
    glClearNamedFramebufferfv(fbo.id(), GL_COLOR, 1, none_far);
    glEnablei(GL_BLEND, 0);
    glEnablei(GL_BLEND, 1);
    glBlendFunci(0, GL_ONE, GL_ONE);
    glBlendFunci(1, GL_ONE, GL_ONE);
    glBlendEquationi(0, GL_MIN);
    glBlendEquationi(1, GL_MAX);
    pass.draw(scene, filter, light, view);
    glBlendEquation(GL_FUNC_ADD);
    glDisable(GL_BLEND);
    glUseProgram(0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

}  // namespace penumbra::passes
