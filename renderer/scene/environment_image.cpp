// Environment maps: the first subimage, RGB (grey replicated), as float, through
// readFloatImage's checks of type, size and finiteness.
#include "renderer/scene/environment_image.h"

#include <algorithm>

#include "renderer/scene/image_file.h"

namespace penumbra::scene {

std::shared_ptr<const EnvironmentImage> loadEnvironmentImage(const std::filesystem::path& path) {
    const FloatImage file = readFloatImage(path, path.string(), {".exr", ".hdr"},
                                           "an .exr or .hdr file", kMaxEnvironmentSize, 3);
    const int channels = file.channels >= 3 ? 3 : 1;  // two channels: grey and alpha
    auto image = std::make_shared<EnvironmentImage>();
    image->width = file.width;
    image->height = file.height;
    const auto pixels =
        static_cast<std::size_t>(file.width) * static_cast<std::size_t>(file.height);
    image->rgb.resize(pixels * 3);
    for (std::size_t i = 0; i < pixels; ++i)
        for (std::size_t c = 0; c < 3; ++c) {
            const float v =
                file.pixels[i * static_cast<std::size_t>(file.channels) + (channels == 3 ? c : 0)];
            image->rgb[i * 3 + c] = std::max(v, 0.0f);
        }
    return image;
}

}  // namespace penumbra::scene
