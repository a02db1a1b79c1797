// The shade pass: see shade.h.
#include "renderer/passes/shade.h"

#include "renderer/core/error.h"
#include "renderer/passes/bindings.h"

namespace penumbra::passes {
namespace {
struct GpuLight {  // std430 mirror of shade.frag's GpuLight
    glm::vec4 corners[4];
    glm::vec4 forward;
    glm::vec4 radiance;
};
}  // namespace

Shade::Shade(int width, int height)
    : width_(width),
      height_(height),
      beauty_(gl::createTexture2D(GL_RGBA32F, width, height, "beauty")),
      visibility_(gl::createTexture2D(GL_R32F, width, height, "visibility")),
      fbo_(gl::createFramebuffer("shade")),
      program_(gl::buildProgram("shade", {"passes/fullscreen.vert", "passes/shade.frag"})) {
    glNamedFramebufferTexture(fbo_.id(), GL_COLOR_ATTACHMENT0, beauty_.id(), 0);
    glNamedFramebufferTexture(fbo_.id(), GL_COLOR_ATTACHMENT1, visibility_.id(), 0);
    const GLenum bufs[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    glNamedFramebufferDrawBuffers(fbo_.id(), 2, bufs);
    if (glCheckNamedFramebufferStatus(fbo_.id(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw RuntimeError("shade: framebuffer incomplete");
}

void Shade::render(const GBuffer& gbuffer, const gl::Texture& visibility_layers,
                   const std::vector<scene::RectLight>& lights) {
    std::vector<GpuLight> data;
    for (const auto& l : lights) {
        GpuLight g;
        auto c = l.corners();
        for (int i = 0; i < 4; ++i) g.corners[i] = glm::vec4(c[static_cast<size_t>(i)], 1.0f);
        g.forward = glm::vec4(l.forward(), 0.0f);
        glm::vec3 r = l.radiance();
        g.radiance = glm::vec4(r, 0.2126f * r.x + 0.7152f * r.y + 0.0722f * r.z);
        data.push_back(g);
    }
    lights_.upload(std::span<const GpuLight>(data), GL_SHADER_STORAGE_BUFFER, kBindingLights);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
    glViewport(0, 0, width_, height_);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glUseProgram(program_.id());
    glBindTextureUnit(0, gbuffer.position().id());
    glBindTextureUnit(1, gbuffer.normal().id());
    glBindTextureUnit(2, gbuffer.albedo().id());
    glBindTextureUnit(3, visibility_layers.id());
    gl::setUniform(program_, "u_light_count", static_cast<int>(lights.size()));
    fullscreen_.draw();
    glUseProgram(0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

}  // namespace penumbra::passes
