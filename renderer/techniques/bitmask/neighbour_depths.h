// `bitmask` gap filling's depths: per level of a depth layer, each micro-occluder's distance
// with its vertical neighbours' (neighbours.comp), one fetch in the back-projection's loop.
#pragma once

#include "renderer/gl/handles.h"

namespace penumbra::techniques::bitmask {

class NeighbourDepths {
public:
    explicit NeighbourDepths(int map_size);
    // From PYRAMID's (min, max) levels (.r), or at levels 1 and up from RECT_DEPTHS (the
    // microrects' R32F depths) where given.
    void build(const gl::Texture& pyramid, const gl::Texture* rect_depths);
    // RGBA32F, the map's levels: (distance, the one below, the one above, 0)
    const gl::Texture& texture() const { return texture_; }

private:
    int map_size_, levels_;
    gl::Texture texture_;
    gl::Program program_;
};

}  // namespace penumbra::techniques::bitmask
