// `bitmask` gap filling's depths: per level of a depth layer, each micro-occluder's distance
// with its vertical neighbours' (neighbours.comp), one fetch in the back-projection's loop.
#pragma once

#include "renderer/gl/handles.h"

namespace penumbra::techniques::bitmask {

class NeighbourDepths {
public:
    // OWN_IDS: .w packs each micro-occluder's owner (neighbours.comp).
    explicit NeighbourDepths(int map_size, bool own_ids = false);
    // From PYRAMID's (min, max) levels (.r), or at levels 1 and up from RECT_DEPTHS (the
    // microrects' R32F depths) where given; with OWN_IDS, the owners from OWNERS (level 0, and
    // with RECT_DEPTHS the levels above).
    void build(const gl::Texture& pyramid, const gl::Texture* rect_depths,
               const gl::Texture* owners = nullptr);
    // RGBA32F, the map's levels: (distance, the one below, the one above, packed owner or 0)
    const gl::Texture& texture() const { return texture_; }

private:
    int map_size_, levels_;
    bool own_ids_;
    gl::Texture texture_;
    gl::Program program_;
};

}  // namespace penumbra::techniques::bitmask
