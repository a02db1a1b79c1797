// Image files read with OpenImageIO: see image_file.h.
#include "renderer/scene/image_file.h"

#include <algorithm>
#include <cctype>
#include <cmath>

#include <OpenImageIO/imageio.h>

#include "renderer/core/error.h"
#include "renderer/core/regular_file.h"

namespace penumbra::scene {
namespace {
std::string oneLine(std::string why) {
    std::replace(why.begin(), why.end(), '\n', ' ');
    return why.empty() ? "" : ": " + why;
}
}  // namespace

FloatImage readFloatImage(const std::filesystem::path& path, const std::string& label,
                          std::initializer_list<std::string_view> extensions,
                          std::string_view expected, int max_size, int channels) {
    std::string extension = path.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (std::find(extensions.begin(), extensions.end(), extension) == extensions.end())
        throw InputError(label + ": expected " + std::string(expected));
    requireRegularFile(path, label);

    auto input = OIIO::ImageInput::open(path.string());
    if (!input) throw InputError(label + ": cannot read image" + oneLine(OIIO::geterror()));
    const OIIO::ImageSpec& spec = input->spec();
    if (spec.width < 1 || spec.height < 1 || spec.depth != 1 || spec.nchannels < 1)
        throw InputError(label + ": not a 2D image");
    if (spec.width > max_size || spec.height > max_size)
        throw InputError(label + ": image too large (" + std::to_string(spec.width) + "x" +
                         std::to_string(spec.height) + ", limit " + std::to_string(max_size) + ")");

    FloatImage image;
    image.width = spec.width;
    image.height = spec.height;
    image.channels = std::min(channels, spec.nchannels);
    const auto count = static_cast<std::size_t>(spec.width) * static_cast<std::size_t>(spec.height);
    image.pixels.resize(count * static_cast<std::size_t>(image.channels));
    if (!input->read_image(0, 0, 0, image.channels, OIIO::TypeDesc::FLOAT, image.pixels.data()))
        throw InputError(label + ": cannot read pixels" + oneLine(input->geterror()));
    input->close();
    for (std::size_t i = 0; i < image.pixels.size(); ++i)
        if (!std::isfinite(image.pixels[i])) {
            const std::size_t pixel = i / static_cast<std::size_t>(image.channels);
            throw InputError(label + ": non-finite pixel at (" +
                             std::to_string(pixel % static_cast<std::size_t>(spec.width)) + ", " +
                             std::to_string(pixel / static_cast<std::size_t>(spec.width)) + ")");
        }
    return image;
}

}  // namespace penumbra::scene
