// `bitmask`'s screen-sized intermediate maps (Schwarz & Stamminger, Fig. 3): the search-area
// map and two LOQ maps (level, class, budget) that the bilateral filter ping-pongs between, and
// the stencil that sends only the penumbra to the back-projection.
#pragma once

#include "renderer/gl/handles.h"

namespace penumbra::techniques::bitmask {

class LoqTargets {
public:
    LoqTargets(int width, int height);
    // Binds colour 0 = search areas, colour 1 = LOQ map 0, viewport = the image.
    void bindClassify();
    // Binds LOQ map I alone.
    void bindLoq(int i);

    int width() const { return width_; }
    int height() const { return height_; }
    const gl::Texture& area() const { return area_; }
    const gl::Texture& loq(int i) const { return loq_[i]; }
    // DEPTH24_STENCIL8: 1 where the visibility pass back-projects (pixel_passes.cpp)
    const gl::Texture& stencil() const { return stencil_; }

private:
    int width_, height_;
    gl::Texture area_, loq_[2], stencil_;
    gl::Framebuffer classify_fbo_, loq_fbo_[2];
};

}  // namespace penumbra::techniques::bitmask
