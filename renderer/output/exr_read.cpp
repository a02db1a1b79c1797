// OpenEXR reading through OpenEXR's Imf API: see exr.h. Every channel is read into FLOAT slices
// (OpenEXR converts), a strip of rows at a time; only regular, bounded, flat files are read.
#include <Imath/ImathBox.h>
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFloatAttribute.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfIntAttribute.h>
#include <OpenEXR/ImfMatrixAttribute.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <OpenEXR/ImfTestFile.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <new>

#include "renderer/core/error.h"
#include "renderer/core/exr_header.h"
#include "renderer/core/memory_limit.h"
#include "renderer/core/regular_file.h"
#include "renderer/output/exr.h"
#include "renderer/output/exr_threads.h"

namespace penumbra::output {

namespace {

// Images larger than this many samples (width * height * channels) are refused on read: a
// corrupt header must not make us allocate without bound. 2^32 floats is 16 GiB.
constexpr int64_t kMaxSamples = int64_t{1} << 32;

// Reading order: R, G, B, A first (as OpenImageIO does), then the rest in the file's
// alphabetical order.
int channelRank(const std::string& name) {
    static const char* const kBeauty[] = {"R", "G", "B", "A"};
    for (int i = 0; i < 4; ++i)
        if (name == kBeauty[i]) return i;
    return 4;
}

std::array<float, 16> fromM44f(const Imath::M44f& m) {
    std::array<float, 16> r{};
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) r[static_cast<size_t>(4 * i + j)] = m[i][j];
    return r;
}

// The checks before OpenEXR opens PATH: a regular file (a FIFO or device would block or never
// end), readable, OpenEXR, not deep.
void checkExrFile(const std::filesystem::path& path, const std::string& where) {
    if (const std::string why = notRegularFileReason(path); !why.empty())
        throw UnreadableImage(where + why);

    std::ifstream in(path, std::ios::binary);
    if (!in) throw UnreadableImage(where + "cannot open: " + std::strerror(errno));
    bool tiled = false, deep = false, multiPart = false;
    if (!Imf::isOpenExrFile(path.c_str(), tiled, deep, multiPart))
        throw UnreadableImage(where + "not an OpenEXR file");
    if (deep) throw UnreadableImage(where + "deep OpenEXR images are not supported");
    std::error_code error;
    const std::uintmax_t size = std::filesystem::file_size(path, error);
    if (error) throw UnreadableImage(where + "cannot read its size: " + error.message());
    if (const std::string why = exrHeaderProblem(in, size); !why.empty())
        throw UnreadableImage(where + why);
}

// CHANNELS (in reading order) with the colour channels first where there are no plain R, G, B:
// those of the alphabetically first layer that has any ("diffuse.R", "diffuse.G", ...), in
// R, G, B, A order, else Y. The others keep their order.
void colourFirst(std::vector<std::pair<std::string, PixelType>>& channels) {
    const auto named = [&](const std::string& name) {
        return std::find_if(channels.begin(), channels.end(),
                            [&](const auto& c) { return c.first == name; });
    };
    if (named("R") != channels.end() || named("G") != channels.end() ||
        named("B") != channels.end())
        return;
    std::string layer;
    for (const auto& [name, type] : channels) {
        const size_t dot = name.rfind('.');
        if (dot == std::string::npos || dot == 0) continue;
        const std::string suffix = name.substr(dot + 1);
        if ((suffix == "R" || suffix == "G" || suffix == "B") &&
            (layer.empty() || name.substr(0, dot) < layer))
            layer = name.substr(0, dot);
    }
    std::vector<std::string> first;
    if (layer.empty())
        first = {"Y"};
    else
        for (const char* c : {"R", "G", "B", "A"}) first.push_back(layer + "." + c);
    auto at = channels.begin();
    for (const std::string& name : first)
        if (const auto it = named(name); it != channels.end()) {
            std::rotate(at, it, it + 1);  // moves it to AT, the rest keeping their order
            ++at;
        }
}

// HEADER's channels (none subsampled) with their types, in reading order.
std::vector<std::pair<std::string, PixelType>> channelList(const Imf::Header& header,
                                                           const std::string& where) {
    std::vector<std::pair<std::string, PixelType>> channels;
    for (auto it = header.channels().begin(); it != header.channels().end(); ++it) {
        if (it.channel().xSampling != 1 || it.channel().ySampling != 1)
            throw UnreadableImage(where + "channel '" + it.name() +
                                  "' is subsampled, which is not supported");
        channels.emplace_back(it.name(),
                              it.channel().type == Imf::HALF ? PixelType::Half : PixelType::Float);
    }
    std::stable_sort(channels.begin(), channels.end(), [](const auto& a, const auto& b) {
        return channelRank(a.first) < channelRank(b.first);
    });
    return channels;
}

// Decodes FILE's WINDOW into IMAGE's channels a strip of rows at a time, each channel growing
// with what decoded.
void readStrips(Imf::InputFile& file, const Imath::Box2i& window, Image& image) {
    const int64_t width = image.width, height = image.height;
    const size_t xStride = sizeof(float);
    const size_t yStride = sizeof(float) * static_cast<size_t>(width);
    constexpr int64_t kStripRows = 256;
    for (int64_t row = 0; !image.channels.empty() && row < height; row += kStripRows) {
        const int64_t rows = std::min(kStripRows, height - row);
        const int y0 = window.min.y + static_cast<int>(row);
        const int y1 = y0 + static_cast<int>(rows) - 1;
        const Imath::Box2i strip(Imath::V2i(window.min.x, y0), Imath::V2i(window.max.x, y1));
        Imf::FrameBuffer frame;
        for (ImageChannel& c : image.channels) {
            c.pixels.resize(static_cast<size_t>((row + rows) * width));
            float* first = c.pixels.data() + static_cast<size_t>(row * width);
            frame.insert(c.name, Imf::Slice::Make(Imf::FLOAT, first, strip, xStride, yStride));
        }
        file.setFrameBuffer(frame);
        file.readPixels(y0, y1);
    }
}

// HEADER's own attributes (not those every header holds) of the types Image keeps.
void readAttributes(const Imf::Header& header, Image& image) {
    const Imf::Header standard(1, 1);  // the attributes every header holds: not ours
    for (auto it = header.begin(); it != header.end(); ++it) {
        if (standard.find(it.name()) != standard.end()) continue;
        const Imf::Attribute& attribute = it.attribute();
        if (const auto* s = dynamic_cast<const Imf::StringAttribute*>(&attribute))
            image.attributes.emplace_back(it.name(), s->value());
        else if (const auto* i = dynamic_cast<const Imf::IntAttribute*>(&attribute))
            image.int_attributes.emplace_back(it.name(), i->value());
        else if (const auto* f = dynamic_cast<const Imf::FloatAttribute*>(&attribute))
            image.float_attributes.emplace_back(it.name(), f->value());
        else if (const auto* m = dynamic_cast<const Imf::M44fAttribute*>(&attribute))
            image.matrix_attributes.emplace_back(it.name(), fromM44f(m->value()));
    }
}

}  // namespace

Image readExr(const std::filesystem::path& path, const ExrReadLimits& limits) {
    const std::string where = path.string() + ": ";
    checkExrFile(path, where);
    useExrWorkerThreads();
    try {
        Imf::InputFile file(path.c_str());
        const Imf::Header& header = file.header();
        const Imath::Box2i window = header.dataWindow();
        const int64_t width = int64_t{window.max.x} - window.min.x + 1;
        const int64_t height = int64_t{window.max.y} - window.min.y + 1;
        if (width <= 0 || height <= 0 || width > INT32_MAX || height > INT32_MAX)
            throw UnreadableImage(where + "empty or invalid data window");

        if (limits.max_side > 0 && (width > limits.max_side || height > limits.max_side))
            throw ImageTooLarge(where + "image too large (" + std::to_string(width) + "x" +
                                std::to_string(height) + ", limit " +
                                std::to_string(limits.max_side) + ")");
        auto channels = channelList(header, where);
        if (limits.colour_first) colourFirst(channels);
        if (limits.channels > 0 && channels.size() > static_cast<size_t>(limits.channels))
            channels.resize(static_cast<size_t>(limits.channels));
        const auto nChannels = static_cast<int64_t>(channels.size());
        if (nChannels > 0 && width * height > kMaxSamples / nChannels)
            throw UnreadableImage(where + "image too large (" + std::to_string(width) + "x" +
                                  std::to_string(height) + ", " + std::to_string(nChannels) +
                                  " channels)");

        // Within the memory limit as declared; then decoded a strip of rows at a time into
        // channels that grow with what decoded, so a header that declares more pixels than
        // the file holds costs only what the file holds.
        try {
            requireMemory(
                saturatingProduct({static_cast<std::uint64_t>(width),
                                   static_cast<std::uint64_t>(height),
                                   static_cast<std::uint64_t>(nChannels), 4}),
                path.string(),
                "reading its " + std::to_string(width) + "x" + std::to_string(height) + " pixels");
        } catch (const InputError& e) {
            throw UnreadableImage(e.what());
        }
        Image image;
        image.width = static_cast<int>(width);
        image.height = static_cast<int>(height);
        for (const auto& [name, type] : channels) image.channels.push_back({name, type, {}});
        readStrips(file, window, image);
        readAttributes(header, image);
        return image;
    } catch (const UnreadableImage&) {
        throw;
    } catch (const std::bad_alloc&) {
        throw UnreadableImage(where + "out of memory reading the image");
    } catch (const std::exception& e) {
        throw UnreadableImage(where + e.what());
    }
}

bool isReadableExr(const std::filesystem::path& path) {
    try {
        (void)readExr(path);
        return true;
    } catch (const UnreadableImage&) {
        return false;
    }
}

}  // namespace penumbra::output
