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
}  // namespace

DepthRanges::DepthRanges(int map_size, Accel accel, int ysm_size, bool far_layer, bool own_ids,
                         bool others_first)
    : map_size_(map_size),
      others_first_(far_layer && others_first),
      hsm_(map_size, "bitmask hsm", nullptr, own_ids || others_first_),
      depth_pass_("bitmask light depth", own_ids || others_first_
                                             ? passes::LightDepthPass::Output::DistanceAndIds
                                             : passes::LightDepthPass::Output::Distance) {
    if (far_layer) {
        far_ = std::make_unique<passes::DistancePyramid>(map_size_, "bitmask far layer",
                                                         &hsm_.depth(), own_ids);
        peel_pass_ = std::make_unique<passes::LightDepthPass>(
            "bitmask far layer peel", "techniques/bitmask/peel.frag", own_ids || others_first_);
    }
    if (accel == Accel::Hsm) return;
    ysm_ = accel == Accel::Ysm;
    mssm_base_ = accel == Accel::Ysm ? std::max(0, log2Of(map_size_ / ysm_size)) : 0;
    const int size = map_size_ >> mssm_base_;
    // Layers 0 .. log2(size) - 2: an extent wider than two neighbourhoods of the top layer
    // (up to the whole part, 4 of them) takes up to 4 x 4 of them (search.glsl, mssmRange), so
    // the two layers above it, which few queries reach, are never built.
    mssm_layers_ = std::max(1, log2Of(size) - 1);
    mssm_ = gl::createTexture2DArray(GL_RG32F, size, size, mssm_layers_,
                                     accel == Accel::Ysm ? "bitmask ysm" : "bitmask mssm");
    mssm_program_ = gl::buildProgram("bitmask mssm", {"techniques/bitmask/mssm.comp"});
}

void DepthRanges::renderMap(const passes::GpuScene& scene, const scene::RectLight& light,
                            const glm::mat4& view_proj) {
    hsm_.render(depth_pass_, scene, light, view_proj);
}

void DepthRanges::renderFarLayer(const passes::GpuScene& scene, const scene::RectLight& light,
                                 const glm::mat4& view_proj) {
    far_->beginDraw();
    glUseProgram(peel_pass_->program().id());
    gl::setUniform(peel_pass_->program(), "u_peel_gap", kPeelGap);
    glBindTextureUnit(BITMASK_UNIT_PEEL_FRONT, hsm_.texture().id());
    gl::setUniform(peel_pass_->program(), "u_others_first", others_first_ ? 1 : 0);
    if (others_first_) glBindTextureUnit(BITMASK_UNIT_PEEL_FRONT_OWNERS, hsm_.owners().id());
    // Near 0 and range 1: the pass's depth is the distance itself, as peel.frag compares it.
    peel_pass_->draw(scene, passes::GpuScene::Filter::Casters, light, {view_proj, 0.0f, 1.0f});
    passes::DistancePyramid::endDraw();
}

void DepthRanges::buildHsm() {
    hsm_.build();
    if (far_) far_->build();
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
            glBindImageTexture(BITMASK_IMAGE_MSSM_BELOW, hsm_.texture().id(), mssm_base_, GL_FALSE,
                               0, GL_READ_ONLY, GL_RG32F);
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
