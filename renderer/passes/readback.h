// Reading textures back to the CPU as float rows, top row first (GL's rows run bottom-up).
#pragma once

#include <vector>

#include "renderer/gl/handles.h"

namespace penumbra::passes {

// COMPONENTS floats per pixel of level 0 (LAYER of an array texture, or -1 for a 2D texture),
// as FORMAT (GL_RED, GL_RGBA, GL_RED_INTEGER...) converted to float.
std::vector<float> readTexture(const gl::Texture& texture, int width, int height, int components,
                               GLenum format, int layer = -1);

}  // namespace penumbra::passes
