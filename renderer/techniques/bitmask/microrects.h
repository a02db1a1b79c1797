// `bitmask`'s microrects (Schwarz & Stamminger 5.2): per level, one micro-occluder per texel
// whose extent is any rectangle of level-0 texels around its reference point, built by a
// greedy two-pass merge of the next finer level; extent and depth in two mip-chained textures.
#pragma once

#include <memory>

#include "renderer/gl/handles.h"
#include "renderer/passes/summed_area_table.h"

namespace penumbra::techniques::bitmask {

class MicroRects {
public:
    // OWN_IDS: build() takes the casters' owners too. FIT: once the next level is built, each
    // level's extents are shrunk to the area of the caster texels inside them, about their mean
    // (microrect_fit.comp, from a summed-area table of the casters: caster_sums.comp).
    explicit MicroRects(int map_size, bool own_ids = false, bool fit = false);
    // Builds levels 1 and up from HSM (level 0 of an RG32F (min, max) pyramid, kEmpty where
    // no caster is); level 0, the micropatches, is the HSM's and is left unwritten. With
    // OWN_IDS, OWNERS (passes::DistancePyramid::owners(), level 0 written) gets each level's
    // microrects' owners: the object id of the nearest texel merged and the nearest distance of
    // those of other objects (microrects.comp).
    void build(const gl::Texture& hsm, const gl::Texture* owners = nullptr);

    // RGBA32F: x0, y0, x1, y1 (level-0 texels); levels 1 and up
    const gl::Texture& extent() const { return extent_; }
    // RG32F: the nearest and the farthest caster texel merged
    const gl::Texture& depth() const { return depth_; }

private:
    int map_size_, levels_;
    bool own_ids_, fit_;
    gl::Texture extent_, depth_;
    std::unique_ptr<passes::SummedAreaTable> sums_;
    gl::Program program_, sums_program_, fit_program_;

    void sumCasters(const gl::Texture& hsm);

    void fitLevel(int level);
};

}  // namespace penumbra::techniques::bitmask
