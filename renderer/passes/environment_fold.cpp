// Environment fold: see environment_fold.h.
#include "renderer/passes/environment_fold.h"

#include "renderer/passes/bindings.h"
#include "renderer/passes/light_depth.h"
#include "renderer/passes/shade.h"

namespace penumbra::passes {

EnvironmentFold::EnvironmentFold(int width, int height, const gl::Buffer& caster_flags)
    : width_(width),
      height_(height),
      caster_flags_(caster_flags),
      sum_(gl::createTexture2D(GL_RGBA32F, width, height, "environment irradiance sum")),
      fbo_(gl::createFramebuffer("environment fold")),
      program_(gl::buildProgram("environment fold",
                                {"passes/fullscreen.vert", "passes/environment_fold.frag"})) {
    glNamedFramebufferTexture(fbo_.id(), GL_COLOR_ATTACHMENT0, sum_.id(), 0);
    checkFramebuffer(fbo_, "environment fold");
}

void EnvironmentFold::begin(const std::vector<scene::RectLight>& lights) {
    uploadGpuLights(lights_, lights);
    const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    glClearNamedFramebufferfv(fbo_.id(), GL_COLOR, 0, zero);
}

void EnvironmentFold::add(const GBuffer& gbuffer, const gl::Texture& visibility_layers, int layer,
                          int light, int count) {
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
    glViewport(0, 0, width_, height_);
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_BLEND);
    glBlendEquation(GL_FUNC_ADD);
    glBlendFunc(GL_ONE, GL_ONE);
    glUseProgram(program_.id());
    glBindTextureUnit(UNIT_SHADE_POSITION, gbuffer.position().id());
    glBindTextureUnit(UNIT_SHADE_NORMAL, gbuffer.normal().id());
    glBindTextureUnit(UNIT_SHADE_ID, gbuffer.id().id());
    glBindTextureUnit(UNIT_SHADE_VISIBILITY, visibility_layers.id());
    gbuffer.bindGeometricNormal();
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kBindingLights, lights_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kBindingCasterFlags, caster_flags_.id());
    gl::setUniform(program_, "u_light", light);
    gl::setUniform(program_, "u_layer", layer);
    gl::setUniform(program_, "u_count", count);
    fullscreen_.draw();
    glDisable(GL_BLEND);
    glUseProgram(0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void EnvironmentFold::end(const gl::Texture& visibility_layers, int layer) {
    glMemoryBarrier(GL_TEXTURE_UPDATE_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT);
    glCopyImageSubData(sum_.id(), GL_TEXTURE_2D, 0, 0, 0, 0, visibility_layers.id(),
                       GL_TEXTURE_2D_ARRAY, 0, 0, 0, layer, width_, height_, 1);
}

}  // namespace penumbra::passes
