// A cheap cover pass and a costly full program under a stencil: the cover settles the pixels it
// can, and the full program runs only on the others (bitmask's, css's and ssm's visibility).
#pragma once

#include <functional>
#include <string>

#include "renderer/gl/handles.h"

namespace penumbra::passes {

// Draws COVER, which writes the pixels it settles (their stencil set to 0) and discards the
// others (left 1), then FULL only where the stencil is 1, early (its fragments never run). The
// bound framebuffer must have a stencil attachment.
void drawCovered(const std::function<void()>& cover, const std::function<void()>& full);

// A DEPTH24_STENCIL8 texture the size of the image, made when first needed or resized.
class CoverStencil {
public:
    explicit CoverStencil(std::string label) : label_(std::move(label)) {}
    // Attaches it, WIDTH x HEIGHT, to FRAMEBUFFER's depth-stencil point; detach() takes it off.
    void attach(GLuint framebuffer, int width, int height);
    static void detach(GLuint framebuffer);

private:
    std::string label_;
    gl::Texture texture_;
    int width_ = 0, height_ = 0;
};

}  // namespace penumbra::passes
