// The casters' distance map from a light's centre and its min/max pyramid: see
// distance_pyramid.h.
#include "renderer/passes/distance_pyramid.h"
#include "glsl/common/bindings.glsl"

#include <bit>

namespace penumbra::passes {

DistancePyramid::DistancePyramid(int size, const char* label, const gl::Texture* shared_depth,
                                 bool with_owners)
    : size_(size), levels_(std::bit_width(static_cast<unsigned>(size))) {
    texture_ = gl::createTexture2D(GL_RG32F, size_, size_, label, levels_);
    if (!shared_depth) {
        depth_ = gl::createTexture2D(GL_DEPTH_COMPONENT32F, size_, size_, label);
        shared_depth = &depth_;
    }
    fbo_ = gl::createFramebuffer(label);
    glNamedFramebufferTexture(fbo_.id(), GL_COLOR_ATTACHMENT0, texture_.id(), 0);
    glNamedFramebufferTexture(fbo_.id(), GL_DEPTH_ATTACHMENT, shared_depth->id(), 0);
    if (with_owners) {
        owners_ = gl::createTexture2D(GL_RG32F, size_, size_, label, levels_);
        glNamedFramebufferTexture(fbo_.id(), GL_COLOR_ATTACHMENT1, owners_.id(), 0);
        const GLenum buffers[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
        glNamedFramebufferDrawBuffers(fbo_.id(), 2, buffers);
    }
    checkFramebuffer(fbo_, label);
    program_ = gl::buildProgram("distance pyramid", {"passes/distance_pyramid.comp"});
}

void DistancePyramid::beginDraw() const {
    beginDepthMapDraw(fbo_.id(), size_);
    const float empty[4] = {kEmpty, kEmpty, 0.0f, 0.0f}, far = 1.0f;
    glClearNamedFramebufferfv(fbo_.id(), GL_COLOR, 0, empty);
    if (owners_.id() != 0) {
        const float none[4] = {-1.0f, kEmpty, 0.0f, 0.0f};
        glClearNamedFramebufferfv(fbo_.id(), GL_COLOR, 1, none);
    }
    glClearNamedFramebufferfv(fbo_.id(), GL_DEPTH, 0, &far);
}

void DistancePyramid::endDraw() {
    glDisable(GL_DEPTH_TEST);
    glUseProgram(0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void DistancePyramid::render(const LightDepthPass& pass, const GpuScene& scene,
                             const scene::RectLight& light, const glm::mat4& view_proj) const {
    beginDraw();
    pass.draw(scene, GpuScene::Filter::Casters, light, {view_proj});
    endDraw();
}

void DistancePyramid::build() const {
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT);
    glUseProgram(program_.id());
    for (int level = 1; level < levels_; ++level) {
        glBindImageTexture(IMAGE_PYRAMID_FINER, texture_.id(), level - 1, GL_FALSE, 0, GL_READ_ONLY,
                           GL_RG32F);
        glBindImageTexture(IMAGE_PYRAMID_COARSER, texture_.id(), level, GL_FALSE, 0, GL_WRITE_ONLY,
                           GL_RG32F);
        const auto groups = static_cast<GLuint>(((size_ >> level) + 7) / 8);
        glDispatchCompute(groups, groups, 1);
        glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
    }
    glUseProgram(0);
}

}  // namespace penumbra::passes
