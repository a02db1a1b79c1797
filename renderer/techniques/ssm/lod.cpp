// `ssm`'s micro-patch level of detail (lod.comp): neighbouring micro-patches of similar depth
// merged into one where their penumbra quads dwarf them, so the splat's work stays bounded.
#include "glsl/techniques/ssm/bindings.glsl"
#include "renderer/gl/param_uniforms.h"
#include "renderer/techniques/ssm/ssm.h"

#include <algorithm>
#include <string>

namespace penumbra::techniques::ssm {

void Ssm::prepareLod() {
    if (!lod_) return;
    for (int phase = 0; phase < 3; ++phase)
        lod_programs_[size_t(phase)] = gl::buildProgram("ssm lod", {"techniques/ssm/lod.comp"},
                                                        {{"LOD_PHASE", std::to_string(phase)}});
    lod_levels_ = 1;  // the pyramid's: up to kMaxLodLevel
    while (lod_levels_ <= kMaxLodLevel && (map_size_ >> lod_levels_) > 0) ++lod_levels_;
    lod_pyramid_ =
        gl::createTexture2D(GL_RGBA32F, map_size_, map_size_, "ssm lod pyramid", lod_levels_);
    lod_patches_ = gl::createTexture2D(GL_RGBA32F, map_size_, map_size_, "ssm lod micro-patches");
    lod_slopes_ = gl::createTexture2D(GL_RG32F, map_size_, map_size_, "ssm lod slopes");
}

// The pyramid level by level (phases 0 and 1), then the merged map (phase 2): a program each.
void Ssm::buildLod(const scene::RectLight& light, const LightWindow& occ, const LightWindow& soft,
                   int side) {
    const auto& map = *occluder_maps_[size_t(side)];
    glBindTextureUnit(SSM_UNIT_LOD_DEPTH, map.depth.id());
    glBindTextureUnit(SSM_UNIT_LOD_IDS, map.ids.id());
    glBindTextureUnit(SSM_UNIT_LOD_PYRAMID, lod_pyramid_.id());
    const auto use = [&](int phase) -> const gl::Program& {
        const auto& p = lod_programs_[size_t(phase)];
        glUseProgram(p.id());
        gl::setUniform(p, "u_empty", emptyDepth(side));
        gl::setUniform(p, "u_occ_near", occ.near);
        gl::setUniform(p, "u_occ_range", occ.far - occ.near);
        gl::setUniform(p, "u_occ_texel", occ.size / static_cast<float>(map_size_));
        gl::setUniform(p, "u_light_half", 0.5f * light.size);
        gl::setUniform(p, "u_receiver_far", soft.far);
        gl::setParamUniforms(p, kSsmParams, params_);  // lod, lod_depth
        // The sample masks back-project a merged block's plane (splat.frag); the area sum's
        // intervals need patches parallel to the light.
        gl::setUniform(p, "u_planar", samples_ ? 1 : 0);
        return p;
    };
    const auto dispatch = [](int size) {
        const auto groups = static_cast<GLuint>((std::max(size, 1) + 7) / 8);
        glDispatchCompute(groups, groups, 1);
        glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    };
    for (int level = 0; level < lod_levels_; ++level) {
        const auto& p = use(level == 0 ? 0 : 1);
        gl::setUniform(p, "u_level", level);
        glBindImageTexture(SSM_IMAGE_LOD_LEVEL, lod_pyramid_.id(), level, GL_FALSE, 0,
                           GL_WRITE_ONLY, GL_RGBA32F);
        dispatch(map_size_ >> level);
    }
    gl::setUniform(use(2), "u_level", lod_levels_ - 1);
    glBindImageTexture(SSM_IMAGE_LOD_PATCHES, lod_patches_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY,
                       GL_RGBA32F);
    glBindImageTexture(SSM_IMAGE_LOD_SLOPES, lod_slopes_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY,
                       GL_RG32F);
    dispatch(map_size_);
    glUseProgram(0);
}

}  // namespace penumbra::techniques::ssm
