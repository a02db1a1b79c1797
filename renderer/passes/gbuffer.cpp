// The G-buffer pass: see gbuffer.h.
#include "renderer/passes/gbuffer.h"

#include <glm/gtc/matrix_transform.hpp>

#include "renderer/core/error.h"
#include "renderer/passes/bindings.h"

namespace penumbra::passes {

CameraMatrices cameraMatrices(const scene::Camera& c, int width, int height) {
    CameraMatrices m;
    m.position = c.position;
    m.view = glm::lookAt(c.position, c.target, c.up);
    m.projection =
        glm::perspective(glm::radians(c.fov_y),
                         static_cast<float>(width) / static_cast<float>(height), c.near, c.far);
    return m;
}

GBuffer::GBuffer(int width, int height)
    : width_(width),
      height_(height),
      position_(gl::createTexture2D(GL_RGBA32F, width, height, "gbuffer position")),
      normal_(gl::createTexture2D(GL_RGBA32F, width, height, "gbuffer normal")),
      albedo_(gl::createTexture2D(GL_RGBA16F, width, height, "gbuffer albedo")),
      id_(gl::createTexture2D(GL_R32I, width, height, "gbuffer id")),
      geometric_normal_(gl::createTexture2D(GL_RGBA16F, width, height, "gbuffer geometric normal")),
      depth_(gl::createTexture2D(GL_DEPTH_COMPONENT32F, width, height, "gbuffer depth")),
      fbo_(gl::createFramebuffer("gbuffer")),
      programs_(buildGBufferPrograms()) {
    GLuint f = fbo_.id();
    glNamedFramebufferTexture(f, GL_COLOR_ATTACHMENT0, position_.id(), 0);
    glNamedFramebufferTexture(f, GL_COLOR_ATTACHMENT1, normal_.id(), 0);
    glNamedFramebufferTexture(f, GL_COLOR_ATTACHMENT2, albedo_.id(), 0);
    glNamedFramebufferTexture(f, GL_COLOR_ATTACHMENT3, id_.id(), 0);
    glNamedFramebufferTexture(f, GL_COLOR_ATTACHMENT4, geometric_normal_.id(), 0);
    glNamedFramebufferTexture(f, GL_DEPTH_ATTACHMENT, depth_.id(), 0);
    const GLenum bufs[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2,
                           GL_COLOR_ATTACHMENT3, GL_COLOR_ATTACHMENT4};
    glNamedFramebufferDrawBuffers(f, 5, bufs);
    if (glCheckNamedFramebufferStatus(f, GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw RuntimeError("gbuffer: framebuffer incomplete");
}

GBufferPrograms buildGBufferPrograms() {
    const auto build = [](const char* label, const char* textured) {
        return gl::buildProgram(label, {"passes/gbuffer.vert", "passes/gbuffer.frag"},
                                {{"TEXTURED", textured}});
    };
    return {build("gbuffer", "0"), build("gbuffer textured", "1")};
}

void drawGBuffer(GLuint fbo, int width, int height, const GBufferPrograms& programs,
                 const GpuScene& scene, const glm::mat4& view, const glm::mat4& projection) {
    const float zero[4] = {0, 0, 0, 0};
    const GLint none[4] = {-1, -1, -1, -1};
    const float one = 1.0f;
    glClearNamedFramebufferfv(fbo, GL_COLOR, 0, zero);
    glClearNamedFramebufferfv(fbo, GL_COLOR, 1, zero);
    glClearNamedFramebufferfv(fbo, GL_COLOR, 2, zero);
    glClearNamedFramebufferiv(fbo, GL_COLOR, 3, none);
    glClearNamedFramebufferfv(fbo, GL_COLOR, 4, zero);  // a no-op where FBO has 4 targets
    glClearNamedFramebufferfv(fbo, GL_DEPTH, 0, &one);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glViewport(0, 0, width, height);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
    for (const gl::Program* p : {&programs.textured, &programs.plain}) {
        glUseProgram(p->id());
        gl::setUniform(*p, "u_view", view);
        gl::setUniform(*p, "u_projection", projection);
    }
    scene.draw(programs.plain, GpuScene::Filter::All, 1, &programs.textured);
    glUseProgram(0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void GBuffer::bindGeometricNormal() const {
    glBindTextureUnit(kUnitGeometricNormal, geometric_normal_.id());
}

void GBuffer::render(const GpuScene& scene, const CameraMatrices& camera) {
    drawGBuffer(fbo_.id(), width_, height_, programs_, scene, camera.view, camera.projection);
}

}  // namespace penumbra::passes
