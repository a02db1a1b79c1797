// Environment maps read with OpenImageIO: the first subimage, RGB (grey replicated), as float,
// after checking the type, the size and every pixel's finiteness.
#include "renderer/scene/environment_image.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <vector>

#include <OpenImageIO/imageio.h>

#include "renderer/core/error.h"

namespace penumbra::scene {

std::shared_ptr<const EnvironmentImage> loadEnvironmentImage(const std::filesystem::path& path) {
    const std::string label = path.string();
    std::string extension = path.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (extension != ".exr" && extension != ".hdr")
        throw InputError(label + ": expected an .exr or .hdr file");
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
        throw InputError(label + ": " +
                         (std::filesystem::exists(path, ec) ? "not a file" : "no such file"));

    auto input = OIIO::ImageInput::open(label);
    if (!input) {
        std::string why = OIIO::geterror();
        std::replace(why.begin(), why.end(), '\n', ' ');
        throw InputError(label + ": cannot read image" + (why.empty() ? "" : ": " + why));
    }
    const OIIO::ImageSpec& spec = input->spec();
    if (spec.width < 1 || spec.height < 1 || spec.depth != 1 || spec.nchannels < 1)
        throw InputError(label + ": not a 2D image");
    if (spec.width > kMaxEnvironmentSize || spec.height > kMaxEnvironmentSize)
        throw InputError(label + ": image too large (" + std::to_string(spec.width) + "x" +
                         std::to_string(spec.height) + ", limit " +
                         std::to_string(kMaxEnvironmentSize) + ")");

    const int channels = spec.nchannels >= 3 ? 3 : 1;
    const auto pixels =
        static_cast<std::size_t>(spec.width) * static_cast<std::size_t>(spec.height);
    std::vector<float> data(pixels * static_cast<std::size_t>(channels));
    if (!input->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, data.data())) {
        std::string why = input->geterror();
        std::replace(why.begin(), why.end(), '\n', ' ');
        throw InputError(label + ": cannot read pixels" + (why.empty() ? "" : ": " + why));
    }
    input->close();

    auto image = std::make_shared<EnvironmentImage>();
    image->width = spec.width;
    image->height = spec.height;
    image->rgb.resize(pixels * 3);
    for (std::size_t i = 0; i < pixels; ++i) {
        for (int c = 0; c < 3; ++c) {
            const float v = data[i * static_cast<std::size_t>(channels) +
                                 static_cast<std::size_t>(channels == 3 ? c : 0)];
            if (!std::isfinite(v))
                throw InputError(label + ": non-finite pixel at (" +
                                 std::to_string(i % static_cast<std::size_t>(spec.width)) + ", " +
                                 std::to_string(i / static_cast<std::size_t>(spec.width)) + ")");
            image->rgb[i * 3 + static_cast<std::size_t>(c)] = std::max(v, 0.0f);
        }
    }
    return image;
}

}  // namespace penumbra::scene
