// Tone-mapped PNG preview: see preview.h. Encoded in memory with stb_image_write, then written
// through writeAtomically so a failure never leaves a partial PNG under the final name.
#include "renderer/output/preview.h"

#include <stb_image_write.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <vector>

#include "renderer/core/atomic_file.h"
#include "renderer/core/error.h"
#include "renderer/output/tone_map.h"

namespace penumbra::output {

namespace {

void appendBytes(void* context, void* data, int size) {
    auto* out = static_cast<std::vector<unsigned char>*>(context);
    const auto* bytes = static_cast<const unsigned char*>(data);
    out->insert(out->end(), bytes, bytes + size);
}

}  // namespace

void writePngPreview(const std::filesystem::path& path, const Image& image, float exposure) {
    const ImageChannel* rgb[3] = {image.find("R"), image.find("G"), image.find("B")};
    for (int c = 0; c < 3; ++c)
        if (!rgb[c])
            throw InputError(path.string() + ": preview needs channels R, G and B; channel '" +
                             std::string(1, "RGB"[c]) + "' is missing");
    if (image.width <= 0 || image.height <= 0)
        throw RuntimeError(path.string() + ": cannot write an empty preview");
    const size_t pixels = static_cast<size_t>(image.width) * static_cast<size_t>(image.height);
    for (const auto* c : rgb)
        if (c->pixels.size() != pixels)
            throw RuntimeError(path.string() + ": channel '" + c->name + "' has the wrong size");

    std::vector<unsigned char> rgb8(pixels * 3);
    for (size_t i = 0; i < pixels; ++i)
        for (int c = 0; c < 3; ++c) rgb8[i * 3 + c] = toneMap8(rgb[c]->pixels[i], exposure);

    writePngRgb8(path, image.width, image.height, rgb8);
}

void writePngRgb8(const std::filesystem::path& path, int width, int height,
                  const std::vector<unsigned char>& rgb8) {
    if (width <= 0 || height <= 0 ||
        rgb8.size() != static_cast<size_t>(width) * static_cast<size_t>(height) * 3)
        throw RuntimeError(path.string() + ": PNG pixels do not match " + std::to_string(width) +
                           "x" + std::to_string(height));
    std::vector<unsigned char> png;
    if (!stbi_write_png_to_func(appendBytes, &png, width, height, 3, rgb8.data(), width * 3))
        throw RuntimeError(path.string() + ": PNG encoding failed");

    writeAtomically(path, [&](const std::filesystem::path& tmp) {
        std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
        out.write(reinterpret_cast<const char*>(png.data()),
                  static_cast<std::streamsize>(png.size()));
        out.close();
        if (!out) throw std::runtime_error(std::strerror(errno));  // writeAtomically names PATH
    });
}

}  // namespace penumbra::output
