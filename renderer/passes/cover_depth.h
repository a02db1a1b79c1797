// Cheap draws before a costly one, each settling the pixels it can: a later draw runs only on
// the pixels no earlier one settled (bitmask's, css's and ssm's visibility), by a depth test.
#pragma once

#include <functional>
#include <initializer_list>
#include <string>

#include "renderer/gl/handles.h"

namespace penumbra::passes {

// Draws each of DRAWS (full-viewport triangles, passes::Fullscreen) in turn into the bound
// framebuffer, which must have a depth attachment: a draw settles the pixels whose fragments it
// does not discard (their depth, cleared to 1 first, becomes the triangle's 0.5), and a later
// draw's fragments there fail the depth test before its shader runs. That is what skips the
// work: llvmpipe runs a shader's every branch, return and discard included, for every pixel of a
// block that reaches the shader, while a block the early test rejects is not shaded at all.
// The shaders must not write depth; one that discards gets its test early and its depth written
// late, as GL allows and llvmpipe does for a shader that writes no stencil. The depth test is
// off afterwards; the depth function and write mask are as before.
void drawInTurn(std::initializer_list<std::function<void()>> draws);

// drawInTurn({cover, full}): COVER writes the pixels it settles and discards the others, and
// FULL runs on those alone.
void drawCovered(const std::function<void()>& cover, const std::function<void()>& full);

// A 16-bit depth texture the size of the image for drawInTurn() (its two depths, 1 and 0.5, are
// exact there; DEPTH24_STENCIL8 was 1-2 % slower), made when first needed or resized.
class CoverDepth {
public:
    explicit CoverDepth(std::string label) : label_(std::move(label)) {}
    // Attaches it, WIDTH x HEIGHT, to FRAMEBUFFER's depth point; detach() takes it off.
    void attach(GLuint framebuffer, int width, int height);
    static void detach(GLuint framebuffer);

private:
    std::string label_;
    gl::Texture texture_;
    int width_ = 0, height_ = 0;
};

}  // namespace penumbra::passes
