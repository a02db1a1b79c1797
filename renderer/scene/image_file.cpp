// Image files read with OpenImageIO (the module of core/oiio_module.h), OpenEXR files with
// output/exr.h's reader: see image_file.h.
#include "renderer/scene/image_file.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <memory>

#include <fcntl.h>
#include <unistd.h>

#include "renderer/core/error.h"
#include "renderer/core/exr_header.h"
#include "renderer/core/json_bounds.h"
#include "renderer/core/memory_limit.h"
#include "renderer/core/oiio_module.h"
#include "renderer/core/png_chunks.h"
#include "renderer/core/regular_file.h"
#include "renderer/output/exr.h"

namespace penumbra::scene {
namespace {

constexpr int kStripRows = 64;  // rows decoded per read: the most memory a lie in a header costs

std::string reasonSuffix(std::string why) {
    std::replace(why.begin(), why.end(), '\n', ' ');
    return why.empty() ? "" : ": " + quoteText(why);
}

// Throws "<LABEL>: non-finite pixel at (x, y)" for the first NaN or infinity of IMAGE.
void requireFinite(const FloatImage& image, const std::string& label) {
    for (std::size_t i = 0; i < image.pixels.size(); ++i)
        if (!std::isfinite(image.pixels[i])) {
            const std::size_t pixel = i / static_cast<std::size_t>(image.channels);
            const auto width = static_cast<std::size_t>(image.width);
            throw InputError(label + ": non-finite pixel at (" + std::to_string(pixel % width) +
                             ", " + std::to_string(pixel / width) + ")");
        }
}

// Decodes INPUT's first subimage strip by strip into a buffer that grows with what decoded.
FloatImage readOpened(ImageDecoder& input, const std::string& label, int max_size, int channels) {
    const DecoderSpec& spec = input.spec();
    if (spec.width < 1 || spec.height < 1 || spec.depth != 1 || spec.channels < 1)
        throw InputError(label + ": not a 2D image");
    if (spec.width > max_size || spec.height > max_size)
        throw InputError(label + ": image too large (" + std::to_string(spec.width) + "x" +
                         std::to_string(spec.height) + ", limit " + std::to_string(max_size) + ")");
    FloatImage image;
    image.width = spec.width;
    image.height = spec.height;
    image.channels = std::min(channels, spec.channels);
    const auto row =
        static_cast<std::size_t>(spec.width) * static_cast<std::size_t>(image.channels);
    requireMemory(saturatingProduct({row, static_cast<std::uint64_t>(spec.height), 4}), label,
                  "decoding its " + std::to_string(spec.width) + "x" + std::to_string(spec.height) +
                      " pixels");

    // Tiled files are read a row of tiles at a time (the strip rounded up to whole tiles).
    const int step = spec.tile_width > 0 && spec.tile_height > 0
                         ? std::max(1, kStripRows / spec.tile_height) * spec.tile_height
                         : kStripRows;
    for (int y0 = 0; y0 < spec.height; y0 += step) {
        const int y1 = std::min(spec.height, y0 + step);
        image.pixels.resize(row * static_cast<std::size_t>(y1));
        float* out = image.pixels.data() + row * static_cast<std::size_t>(y0);
        if (!input.readRows(y0, y1, image.channels, out))
            throw InputError(label + ": cannot read pixels" + reasonSuffix(input.error()));
    }
    input.close();
    requireFinite(image, label);
    return image;
}

// An OpenEXR file through the project's own reader (output/exr.h: header checks, bounded
// strips, the memory limit), which needs no OpenImageIO module.
FloatImage readExrFile(const std::filesystem::path& path, const std::string& label, int max_size,
                       int channels) {
    // Its messages name PATH: LABEL instead.
    const auto reason = [&](const std::exception& e) {
        std::string why = e.what();
        const std::string prefix = path.string() + ": ";
        if (why.rfind(prefix, 0) == 0) why.erase(0, prefix.size());
        return why;
    };
    output::Image file;
    try {
        file = output::readExr(path,
                               {.channels = channels, .max_side = max_size, .colour_first = true});
    } catch (const output::ImageTooLarge& e) {
        throw InputError(label + ": " + reason(e));
    } catch (const output::UnreadableImage& e) {
        throw InputError(label + ": cannot read image: " + reason(e));
    }
    if (file.channels.empty()) throw InputError(label + ": cannot read image: no channels");
    FloatImage image;
    image.width = file.width;
    image.height = file.height;
    image.channels = static_cast<int>(file.channels.size());
    const auto pixels =
        static_cast<std::size_t>(file.width) * static_cast<std::size_t>(file.height);
    const auto stride = static_cast<std::size_t>(image.channels);
    image.pixels.resize(pixels * stride);
    for (std::size_t c = 0; c < stride; ++c) {
        const std::vector<float>& from = file.channels[c].pixels;
        for (std::size_t i = 0; i < pixels; ++i) image.pixels[i * stride + c] = from[i];
        std::vector<float>().swap(file.channels[c].pixels);  // held once, not twice
    }
    requireFinite(image, label);
    return image;
}

// OpenImageIO's PNG reader leaves libpng's warnings on stderr ("libpng warning: IDAT: CRC
// error") before its own error: the message reaches us through geterror(), so the decoder's
// stderr goes to /dev/null while it runs (loading is single-threaded).
class QuietStderr {
public:
    QuietStderr() {
        std::fflush(stderr);
        saved_ = ::dup(STDERR_FILENO);
        const int null = ::open("/dev/null", O_WRONLY | O_CLOEXEC);
        if (saved_ >= 0 && null >= 0) ::dup2(null, STDERR_FILENO);
        if (null >= 0) ::close(null);
    }
    ~QuietStderr() {
        std::fflush(stderr);
        if (saved_ >= 0) {
            ::dup2(saved_, STDERR_FILENO);
            ::close(saved_);
        }
    }
    QuietStderr(const QuietStderr&) = delete;
    QuietStderr& operator=(const QuietStderr&) = delete;

private:
    int saved_ = -1;
};

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
    if (extension == ".exr") return readExrFile(path, label, max_size, channels);
    if (extension == ".png") {  // before libpng allocates what a chunk declares
        std::error_code error;
        const std::uintmax_t size = std::filesystem::file_size(path, error);
        std::ifstream in(path, std::ios::binary);
        if (const std::string why = error ? "" : pngChunkProblem(in, size); !why.empty())
            throw InputError(label + ": cannot read image: " + why);
    }

    OiioModule& oiio = oiioModule();
    const QuietStderr quiet;
    std::string why;
    auto input = oiio.open(path.string(), why);
    if (!input) throw InputError(label + ": cannot read image" + reasonSuffix(why));
    return readOpened(*input, label, max_size, channels);
}

FloatImage readFloatImageFromMemory(const unsigned char* bytes, std::size_t size,
                                    std::string_view extension, const std::string& label,
                                    int max_size, int channels) {
    if (extension == ".exr")
        if (const std::string why = exrHeaderProblem(bytes, size); !why.empty())
            throw InputError(label + ": cannot read image: " + why);
    OiioModule& oiio = oiioModule();
    const QuietStderr quiet;
    std::string why;
    auto input = oiio.openMemory(bytes, size, std::string(extension), why);
    if (!input) throw InputError(label + ": cannot read image" + reasonSuffix(why));
    return readOpened(*input, label, max_size, channels);
}

}  // namespace penumbra::scene
