// `bitmask`'s microrects: see microrects.h.
#include "renderer/techniques/bitmask/microrects.h"
#include "glsl/techniques/bitmask/bindings.glsl"

#include <bit>

#include "renderer/core/error.h"
#include "renderer/gl/program.h"
#include "renderer/techniques/bitmask/depth_ranges.h"

namespace penumbra::techniques::bitmask {

MicroRects::MicroRects(int map_size, bool own_ids, bool fit)
    : map_size_(map_size),
      levels_(std::bit_width(static_cast<unsigned>(map_size))),
      own_ids_(own_ids),
      fit_(fit) {
    extent_ =
        gl::createTexture2D(GL_RGBA32F, map_size_, map_size_, "bitmask microrect extents", levels_);
    depth_ =
        gl::createTexture2D(GL_RG32F, map_size_, map_size_, "bitmask microrect depths", levels_);
    program_ = gl::buildProgram("bitmask microrects", {"techniques/bitmask/microrects.comp"},
                                {{"OWN_IDS", own_ids ? "1" : "0"}});
    if (fit_) {
        sums_ = std::make_unique<passes::SummedAreaTable>(map_size_, 1, "bitmask caster sums",
                                                          passes::SummedAreaTable::Texel::Unsigned);
        sums_program_ =
            gl::buildProgram("bitmask caster sums", {"techniques/bitmask/caster_sums.comp"});
        fit_program_ =
            gl::buildProgram("bitmask microrect fit", {"techniques/bitmask/microrect_fit.comp"});
    }
}

// The summed-area table of HSM's caster texels: our rows, then the table's columns.
void MicroRects::sumCasters(const gl::Texture& hsm) {
    glUseProgram(sums_program_.id());
    gl::setUniform(sums_program_, "u_empty", DepthRanges::kEmpty);
    glBindImageTexture(BITMASK_IMAGE_CASTER_SUMS_MAP, hsm.id(), 0, GL_FALSE, 0, GL_READ_ONLY,
                       GL_RG32F);
    glBindImageTexture(BITMASK_IMAGE_CASTER_SUMS, sums_->table().id(), 0, GL_FALSE, 0,
                       GL_WRITE_ONLY, GL_RGBA32UI);
    glDispatchCompute(static_cast<GLuint>((map_size_ + 63) / 64), 1, 1);
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    sums_->sumColumns();
}

// Shrinks LEVEL's extents to their coverage; only once the level above has been merged from
// them.
void MicroRects::fitLevel(int level) {
    glUseProgram(fit_program_.id());
    glBindImageTexture(BITMASK_IMAGE_MICRORECT_FIT_EXTENT, extent_.id(), level, GL_FALSE, 0,
                       GL_READ_WRITE, GL_RGBA32F);
    glBindImageTexture(BITMASK_IMAGE_MICRORECT_FIT_SUMS, sums_->table().id(), 0, GL_FALSE, 0,
                       GL_READ_ONLY, GL_RGBA32UI);
    const GLuint groups = static_cast<GLuint>(((map_size_ >> level) + 7) / 8);
    glDispatchCompute(groups, groups, 1);
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
    glUseProgram(program_.id());
}

void MicroRects::build(const gl::Texture& hsm, const gl::Texture* owners) {
    if (own_ids_ && !owners) throw RuntimeError("bitmask microrects: built without owners");
    if (fit_) sumCasters(hsm);
    glUseProgram(program_.id());
    gl::setUniform(program_, "u_empty", DepthRanges::kEmpty);
    glBindImageTexture(BITMASK_IMAGE_MICRORECTS_HSM0, hsm.id(), 0, GL_FALSE, 0, GL_READ_ONLY,
                       GL_RG32F);
    // Level 0 is the HSM's level 0 (micropatches): level 1 merges it directly.
    for (int level = 1; level < levels_; ++level) {
        gl::setUniform(program_, "u_from_hsm", level == 1 ? 1 : 0);
        glBindImageTexture(BITMASK_IMAGE_MICRORECTS_EXTENT_IN, extent_.id(), level - 1, GL_FALSE, 0,
                           GL_READ_ONLY, GL_RGBA32F);
        glBindImageTexture(BITMASK_IMAGE_MICRORECTS_DEPTH_IN, depth_.id(), level - 1, GL_FALSE, 0,
                           GL_READ_ONLY, GL_RG32F);
        glBindImageTexture(BITMASK_IMAGE_MICRORECTS_EXTENT_OUT, extent_.id(), level, GL_FALSE, 0,
                           GL_WRITE_ONLY, GL_RGBA32F);
        glBindImageTexture(BITMASK_IMAGE_MICRORECTS_DEPTH_OUT, depth_.id(), level, GL_FALSE, 0,
                           GL_WRITE_ONLY, GL_RG32F);
        if (own_ids_) {
            glBindImageTexture(BITMASK_IMAGE_MICRORECTS_OWNERS_IN, owners->id(), level - 1,
                               GL_FALSE, 0, GL_READ_ONLY, GL_RG32F);
            glBindImageTexture(BITMASK_IMAGE_MICRORECTS_OWNERS_OUT, owners->id(), level, GL_FALSE,
                               0, GL_WRITE_ONLY, GL_RG32F);
        }
        const GLuint groups = static_cast<GLuint>(((map_size_ >> level) + 7) / 8);
        glDispatchCompute(groups, groups, 1);
        glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
        if (fit_ && level > 1) fitLevel(level - 1);
    }
    if (fit_ && levels_ > 1) fitLevel(levels_ - 1);
    glUseProgram(0);
}

}  // namespace penumbra::techniques::bitmask
