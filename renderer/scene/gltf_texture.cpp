// glTF image decoding with stb_image (the implementation compiled into Debian's libstb), and
// Radiance HDR through OpenImageIO (stb's HDR decoder loops forever on a truncated file).
#include "renderer/scene/gltf_texture.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstring>
#include <memory>

#include <stb_image.h>

#include "renderer/core/json_bounds.h"
#include "renderer/core/memory_limit.h"
#include "renderer/scene/image_file.h"

namespace penumbra::scene {
namespace {

// A Radiance HDR image as 8-bit RGBA, as stb_image converts one (gamma 1/2.2, clamped).
Texture decodeHdr(const unsigned char* bytes, std::size_t size, const std::string& label) {
    const FloatImage image =
        readFloatImageFromMemory(bytes, size, ".hdr", label, kMaxTextureSize, 4);
    Texture texture;
    texture.width = image.width;
    texture.height = image.height;
    const auto pixels =
        static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height);
    texture.rgba.resize(pixels * 4);
    const auto channels = static_cast<std::size_t>(image.channels);
    for (std::size_t i = 0; i < pixels; ++i)
        for (std::size_t c = 0; c < 4; ++c) {
            const bool alpha = c == 3;
            float v = 1.0f;
            if (c < channels && !(alpha && channels < 4))
                v = image.pixels[i * channels + (channels < 3 && !alpha ? 0 : c)];
            if (!alpha) v = std::pow(std::max(v, 0.0f), 1.0f / 2.2f);
            texture.rgba[i * 4 + c] =
                static_cast<std::uint8_t>(std::clamp(v, 0.0f, 1.0f) * 255.0f + 0.5f);
        }
    return texture;
}

}  // namespace

Texture decodeGltfImage(const GltfDocument& doc, int index) {
    const std::string key = "images." + std::to_string(index);
    const tinygltf::Image& image = doc.model.images.at(static_cast<std::size_t>(index));
    const unsigned char* bytes = image.image.data();
    std::size_t size = image.image.size();
    if (image.bufferView >= 0) {
        const auto& views = doc.model.bufferViews;
        if (static_cast<std::size_t>(image.bufferView) >= views.size())
            doc.fail(key + ".bufferView",
                     "bufferView " + std::to_string(image.bufferView) + " does not exist");
        const tinygltf::BufferView& view = views[static_cast<std::size_t>(image.bufferView)];
        if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= doc.model.buffers.size())
            doc.fail(key + ".bufferView", "its buffer does not exist");
        const auto& data = doc.model.buffers[static_cast<std::size_t>(view.buffer)].data;
        if (view.byteOffset > data.size() || view.byteLength > data.size() - view.byteOffset)
            doc.fail(key + ".bufferView", "runs past the end of its buffer");
        bytes = data.data() + view.byteOffset;
        size = view.byteLength;
    } else if (size == 0) {
        doc.fail(key + ".uri", "cannot read image '" + quoteText(image.uri) + "'");
    }
    if (size > static_cast<std::size_t>(INT_MAX)) doc.fail(key, "image data too large");

    const int length = static_cast<int>(size);
    if (stbi_is_hdr_from_memory(bytes, length))
        return decodeHdr(bytes, size, doc.label + ": " + key);
    int width = 0;
    int height = 0;
    int channels = 0;
    if (!stbi_info_from_memory(bytes, length, &width, &height, &channels))
        doc.fail(key, std::string("cannot decode image (") + stbi_failure_reason() + ")");
    if (width < 1 || height < 1 || width > kMaxTextureSize || height > kMaxTextureSize)
        doc.fail(key, "image size " + std::to_string(width) + "x" + std::to_string(height) +
                          " outside 1.." + std::to_string(kMaxTextureSize));
    requireMemory(saturatingProduct({static_cast<std::uint64_t>(width),
                                     static_cast<std::uint64_t>(height), 4 * 2}),
                  doc.label + ": " + key, "decoding the image");
    std::unique_ptr<stbi_uc, void (*)(void*)> pixels(
        stbi_load_from_memory(bytes, length, &width, &height, &channels, 4), stbi_image_free);
    if (!pixels) doc.fail(key, std::string("cannot decode image (") + stbi_failure_reason() + ")");

    Texture texture;
    texture.width = width;
    texture.height = height;
    const std::size_t count =
        static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4;
    texture.rgba.assign(pixels.get(), pixels.get() + count);
    return texture;
}

}  // namespace penumbra::scene
