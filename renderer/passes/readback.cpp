// Texture readback: see readback.h.
#include "renderer/passes/readback.h"

#include <algorithm>
#include <cstdint>

namespace penumbra::passes {

std::vector<float> readTexture(const gl::Texture& texture, int width, int height, int components,
                               GLenum format, int layer) {
    const size_t row = static_cast<size_t>(width) * static_cast<size_t>(components);
    const size_t count = row * static_cast<size_t>(height);
    std::vector<float> data(count);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    const bool integer = format == GL_RED_INTEGER || format == GL_RGBA_INTEGER;
    if (integer) {
        std::vector<std::int32_t> ints(count);
        glGetTextureSubImage(texture.id(), 0, 0, 0, std::max(layer, 0), width, height, 1, format,
                             GL_INT, static_cast<GLsizei>(count * sizeof(std::int32_t)),
                             ints.data());
        std::transform(ints.begin(), ints.end(), data.begin(),
                       [](std::int32_t v) { return static_cast<float>(v); });
    } else {
        glGetTextureSubImage(texture.id(), 0, 0, 0, std::max(layer, 0), width, height, 1, format,
                             GL_FLOAT, static_cast<GLsizei>(count * sizeof(float)), data.data());
    }
    for (int y = 0; y < height / 2; ++y)
        std::swap_ranges(
            data.begin() + static_cast<std::ptrdiff_t>(row * static_cast<size_t>(y)),
            data.begin() + static_cast<std::ptrdiff_t>(row * static_cast<size_t>(y + 1)),
            data.begin() + static_cast<std::ptrdiff_t>(row * static_cast<size_t>(height - 1 - y)));
    return data;
}

}  // namespace penumbra::passes
