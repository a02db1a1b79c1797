// `bitmask` gap filling's depths: see neighbour_depths.h.
#include "renderer/techniques/bitmask/neighbour_depths.h"
#include "glsl/techniques/bitmask/bindings.glsl"

#include <bit>

#include "renderer/gl/program.h"

namespace penumbra::techniques::bitmask {

NeighbourDepths::NeighbourDepths(int map_size, bool own_ids)
    : map_size_(map_size),
      levels_(std::bit_width(static_cast<unsigned>(map_size))),
      own_ids_(own_ids) {
    texture_ = gl::createTexture2D(GL_RGBA32F, map_size_, map_size_,
                                   "bitmask micro-occluder neighbours", levels_);
    program_ = gl::buildProgram("bitmask neighbour depths", {"techniques/bitmask/neighbours.comp"},
                                {{"OWN_IDS", own_ids ? "1" : "0"}});
}

void NeighbourDepths::build(const gl::Texture& pyramid, const gl::Texture* rect_depths,
                            const gl::Texture* owners) {
    glUseProgram(program_.id());
    if (own_ids_ && owners) glBindTextureUnit(BITMASK_UNIT_NEIGHBOURS_OWNERS, owners->id());
    for (int level = 0; level < levels_; ++level) {
        const int size = map_size_ >> level;
        const gl::Texture& source = rect_depths && level > 0 ? *rect_depths : pyramid;
        glBindTextureUnit(BITMASK_UNIT_NEIGHBOURS_SOURCE, source.id());
        gl::setUniform(program_, "u_level", level);
        gl::setUniform(program_, "u_size", size);
        // Coarse micropatches (no microrects) have no owners.
        if (own_ids_)
            gl::setUniform(program_, "u_owned", owners && (level == 0 || rect_depths) ? 1 : 0);
        glBindImageTexture(BITMASK_IMAGE_NEIGHBOURS_OUT, texture_.id(), level, GL_FALSE, 0,
                           GL_WRITE_ONLY, GL_RGBA32F);
        const auto groups = static_cast<GLuint>((size + 7) / 8);
        glDispatchCompute(groups, groups, 1);
    }
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
    glUseProgram(0);
}

}  // namespace penumbra::techniques::bitmask
