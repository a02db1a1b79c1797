// glTF image decoding with stb_image (the implementation compiled into Debian's libstb): the
// bytes come from the image file or data URI tinygltf read, or from a checked bufferView.
#include "renderer/scene/gltf_texture.h"

#include <climits>
#include <cstring>
#include <memory>

#include <stb_image.h>

namespace penumbra::scene {

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
        doc.fail(key + ".uri", "cannot read image '" + image.uri + "'");
    }
    if (size > static_cast<std::size_t>(INT_MAX)) doc.fail(key, "image data too large");

    const int length = static_cast<int>(size);
    int width = 0;
    int height = 0;
    int channels = 0;
    if (!stbi_info_from_memory(bytes, length, &width, &height, &channels))
        doc.fail(key, std::string("cannot decode image (") + stbi_failure_reason() + ")");
    if (width < 1 || height < 1 || width > kMaxTextureSize || height > kMaxTextureSize)
        doc.fail(key, "image size " + std::to_string(width) + "x" + std::to_string(height) +
                          " outside 1.." + std::to_string(kMaxTextureSize));
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
