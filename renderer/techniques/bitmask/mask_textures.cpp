// `bitmask`'s sample tables on the GPU: see mask_textures.h.
#include "renderer/techniques/bitmask/mask_textures.h"

#include <cstdint>

#include "renderer/techniques/bitmask/sample_pattern.h"

namespace penumbra::techniques::bitmask {
namespace {

// An RGBA32UI texture of WIDTH x 2 MASKS.size() / WIDTH texels: texel (i, 2 r + h) holds words
// 4 h .. 4 h + 3 of mask r * WIDTH + i.
gl::Texture maskTexture(const std::vector<Mask>& masks, int width, const char* label) {
    const int rows = static_cast<int>(masks.size()) / width;
    std::vector<std::uint32_t> texels(masks.size() * kMaskWords);
    for (int r = 0; r < rows; ++r)
        for (int h = 0; h < 2; ++h)
            for (int i = 0; i < width; ++i)
                for (int c = 0; c < 4; ++c)
                    texels[((size_t(2 * r + h) * size_t(width)) + size_t(i)) * 4 + size_t(c)] =
                        masks[size_t(r) * size_t(width) + size_t(i)][size_t(4 * h + c)];
    gl::Texture t = gl::createTexture2D(GL_RGBA32UI, width, 2 * rows, label);
    glTextureSubImage2D(t.id(), 0, 0, 0, width, 2 * rows, GL_RGBA_INTEGER, GL_UNSIGNED_INT,
                        texels.data());
    return t;
}

}  // namespace

gl::Buffer halfPlaneBuffer(const std::vector<glm::vec2>& points) {
    auto tables = halfPlaneTables(points);
    tables.x.insert(tables.x.end(), tables.y.begin(), tables.y.end());
    std::vector<std::uint32_t> words;
    words.reserve(tables.x.size() * kMaskWords);
    for (const Mask& m : tables.x) words.insert(words.end(), m.begin(), m.end());
    gl::Buffer b = gl::createBuffer("bitmask half-plane masks");
    glNamedBufferStorage(b.id(), static_cast<GLsizeiptr>(words.size() * sizeof(std::uint32_t)),
                         words.data(), 0);
    return b;
}

gl::Texture pointTexture(const std::vector<glm::vec2>& points) {
    const int n = static_cast<int>(points.size());
    gl::Texture t = gl::createTexture2D(GL_RG32F, n, 1, "bitmask sample points");
    glTextureSubImage2D(t.id(), 0, 0, 0, n, 1, GL_RG, GL_FLOAT, points.data());
    return t;
}

gl::Texture edgeTexture(const std::vector<glm::vec2>& points) {
    return maskTexture(edgeTable(points), kEdgeOffsets, "bitmask edge masks");
}

}  // namespace penumbra::techniques::bitmask
