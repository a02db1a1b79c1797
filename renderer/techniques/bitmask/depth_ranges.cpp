// `bitmask`'s light depth map and acceleration structures: see depth_ranges.h.
#include "renderer/techniques/bitmask/depth_ranges.h"
#include "glsl/techniques/bitmask/bindings.glsl"

#include <algorithm>

#include "renderer/gl/program.h"
#include "renderer/passes/light_depth.h"

namespace penumbra::techniques::bitmask {
namespace {
int log2Of(int n) {
    int l = 0;
    while ((1 << (l + 1)) <= n) ++l;
    return l;
}
GLuint groupsFor(int size) {
    return static_cast<GLuint>((size + 7) / 8);
}

// A framebuffer drawing into level 0 of PYRAMID, depth-tested against DEPTH.
gl::Framebuffer pyramidTarget(const gl::Texture& pyramid, const gl::Texture& depth,
                              const char* label) {
    gl::Framebuffer fbo = gl::createFramebuffer(label);
    glNamedFramebufferTexture(fbo.id(), GL_COLOR_ATTACHMENT0, pyramid.id(), 0);
    glNamedFramebufferTexture(fbo.id(), GL_DEPTH_ATTACHMENT, depth.id(), 0);
    passes::checkFramebuffer(fbo, label);
    return fbo;
}

// Clears FBO's distances to kEmpty and its depth to the far plane, ready to draw.
void beginDistanceDraw(const gl::Framebuffer& fbo, int size) {
    passes::beginDepthMapDraw(fbo.id(), size);
    const float empty[4] = {DepthRanges::kEmpty, DepthRanges::kEmpty, 0.0f, 0.0f}, far = 1.0f;
    glClearNamedFramebufferfv(fbo.id(), GL_COLOR, 0, empty);
    glClearNamedFramebufferfv(fbo.id(), GL_DEPTH, 0, &far);
}

void endDistanceDraw() {
    glDisable(GL_DEPTH_TEST);
    glUseProgram(0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}
}  // namespace

DepthRanges::DepthRanges(int map_size, Accel accel, int ysm_size, bool far_layer)
    : map_size_(map_size),
      levels_(log2Of(map_size) + 1),
      depth_pass_("bitmask light depth", passes::LightDepthPass::Output::Distance) {
    hsm_ = gl::createTexture2D(GL_RG32F, map_size_, map_size_, "bitmask hsm", levels_);
    depth_ = gl::createTexture2D(GL_DEPTH_COMPONENT32F, map_size_, map_size_, "bitmask map depth");
    fbo_ = pyramidTarget(hsm_, depth_, "bitmask light depth map");
    if (far_layer) {
        far_ = gl::createTexture2D(GL_RG32F, map_size_, map_size_, "bitmask far layer", levels_);
        far_fbo_ = pyramidTarget(far_, depth_, "bitmask far layer map");
        peel_pass_ = std::make_unique<passes::LightDepthPass>("bitmask far layer peel",
                                                              "techniques/bitmask/peel.frag");
    }
    hsm_program_ = gl::buildProgram("bitmask hsm", {"techniques/bitmask/hsm.comp"});
    if (accel == Accel::Hsm) return;
    ysm_ = accel == Accel::Ysm;
    mssm_base_ = accel == Accel::Ysm ? std::max(0, log2Of(map_size_ / ysm_size)) : 0;
    const int size = map_size_ >> mssm_base_;
    // Layers 0 .. log2(size) - 1: an extent of the whole part is two neighbourhoods of the
    // layer below the whole-map one (search.glsl, mssmRange), which is never built.
    mssm_layers_ = std::max(1, log2Of(size));
    mssm_ = gl::createTexture2DArray(GL_RG32F, size, size, mssm_layers_,
                                     accel == Accel::Ysm ? "bitmask ysm" : "bitmask mssm");
    mssm_program_ = gl::buildProgram("bitmask mssm", {"techniques/bitmask/mssm.comp"});
}

void DepthRanges::renderMap(const passes::GpuScene& scene, const scene::RectLight& light,
                            const glm::mat4& view_proj) {
    beginDistanceDraw(fbo_, map_size_);
    depth_pass_.draw(scene, passes::GpuScene::Filter::Casters, light, {view_proj});
    endDistanceDraw();
}

void DepthRanges::renderFarLayer(const passes::GpuScene& scene, const scene::RectLight& light,
                                 const glm::mat4& view_proj) {
    beginDistanceDraw(far_fbo_, map_size_);
    glUseProgram(peel_pass_->program().id());
    gl::setUniform(peel_pass_->program(), "u_peel_gap", kPeelGap);
    glBindTextureUnit(BITMASK_UNIT_PEEL_FRONT, hsm_.id());
    // Near 0 and range 1: the pass's depth is the distance itself, as peel.frag compares it.
    peel_pass_->draw(scene, passes::GpuScene::Filter::Casters, light, {view_proj, 0.0f, 1.0f});
    endDistanceDraw();
}

void DepthRanges::buildHsm() {
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT);
    glUseProgram(hsm_program_.id());
    for (const gl::Texture* pyramid : {&hsm_, &far_}) {
        if (!*pyramid) continue;
        for (int level = 1; level < levels_; ++level) {
            glBindImageTexture(BITMASK_IMAGE_HSM_FINER, pyramid->id(), level - 1, GL_FALSE, 0,
                               GL_READ_ONLY, GL_RG32F);
            glBindImageTexture(BITMASK_IMAGE_HSM_COARSER, pyramid->id(), level, GL_FALSE, 0,
                               GL_WRITE_ONLY, GL_RG32F);
            const GLuint groups = groupsFor(map_size_ >> level);
            glDispatchCompute(groups, groups, 1);
            glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
        }
    }
    glUseProgram(0);
}

void DepthRanges::buildMssm() {
    if (mssm_layers_ == 0) return;
    const int size = map_size_ >> mssm_base_;
    glUseProgram(mssm_program_.id());
    const GLuint groups = groupsFor(size);
    // Layer 0 alone (a copy; the YSM never queries it, depth_ranges.h, so its layer 1 reads the
    // HSM level); above it, two layers per dispatch where two are left. Each layer is bound as
    // a 2D image of its own (mssm.comp).
    for (int layer = ysm_ ? 1 : 0; layer < mssm_layers_;) {
        const bool pair = layer > 0 && layer + 1 < mssm_layers_;
        const bool from_hsm = ysm_ ? layer == 1 : layer == 0;
        if (from_hsm)
            glBindImageTexture(BITMASK_IMAGE_MSSM_BELOW, hsm_.id(), mssm_base_, GL_FALSE, 0,
                               GL_READ_ONLY, GL_RG32F);
        else
            glBindImageTexture(BITMASK_IMAGE_MSSM_BELOW, mssm_.id(), 0, GL_FALSE, layer - 1,
                               GL_READ_ONLY, GL_RG32F);
        glBindImageTexture(BITMASK_IMAGE_MSSM, mssm_.id(), 0, GL_FALSE, layer, GL_WRITE_ONLY,
                           GL_RG32F);
        // Without a pair the shader never writes it: bound to the same layer.
        glBindImageTexture(BITMASK_IMAGE_MSSM_NEXT, mssm_.id(), 0, GL_FALSE,
                           pair ? layer + 1 : layer, GL_WRITE_ONLY, GL_RG32F);
        gl::setUniform(mssm_program_, "u_layer", layer);
        gl::setUniform(mssm_program_, "u_pair", pair ? 1 : 0);
        glDispatchCompute(groups, groups, 1);
        glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
        layer += pair ? 2 : 1;
    }
    glUseProgram(0);
}

}  // namespace penumbra::techniques::bitmask
