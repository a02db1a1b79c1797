// `bitmask`'s screen-sized intermediate maps (Schwarz & Stamminger, Fig. 3): the search-area
// map and two LOQ maps (level, class, budget) that the bilateral filter ping-pongs between, and
// the depth buffer that sends only the penumbra to the back-projection (passes::drawCovered).
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

private:
    int width_, height_;
    gl::Texture area_, loq_[2];
    gl::Framebuffer classify_fbo_, loq_fbo_[2];
};

}  // namespace penumbra::techniques::bitmask
