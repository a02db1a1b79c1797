// OpenEXR reading and writing through OpenEXR's Imf API: see exr.h. Half channels are converted
// to half buffers for writing; every channel is read into FLOAT slices (OpenEXR converts).
#include "renderer/output/exr.h"

#include <Imath/ImathBox.h>
#include <Imath/half.h>
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFloatAttribute.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfIntAttribute.h>
#include <OpenEXR/ImfMatrixAttribute.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <OpenEXR/ImfTestFile.h>
#include <OpenEXR/ImfThreading.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <mutex>
#include <new>
#include <set>
#include <thread>

#include "renderer/core/atomic_file.h"
#include "renderer/core/error.h"
#include "renderer/core/memory_limit.h"
#include "renderer/core/regular_file.h"

namespace penumbra::output {

namespace {

// Images larger than this many samples (width * height * channels) are refused on read: a
// corrupt header must not make us allocate without bound. 2^32 floats is 16 GiB.
constexpr int64_t kMaxSamples = int64_t{1} << 32;

// ZIP compression is costly single-threaded; give OpenEXR's global pool some workers once.
void useWorkerThreads() {
    static std::once_flag once;
    std::call_once(once, [] {
        unsigned n = std::thread::hardware_concurrency();
        if (Imf::globalThreadCount() == 0 && n > 1)
            Imf::setGlobalThreadCount(static_cast<int>(std::min(n, 8u)));
    });
}

// Reading order: R, G, B, A first (as OpenImageIO does), then the rest in the file's
// alphabetical order.
int channelRank(const std::string& name) {
    static const char* const kBeauty[] = {"R", "G", "B", "A"};
    for (int i = 0; i < 4; ++i)
        if (name == kBeauty[i]) return i;
    return 4;
}

void checkImage(const std::filesystem::path& path, const Image& image) {
    if (image.width <= 0 || image.height <= 0)
        throw RuntimeError(path.string() + ": cannot write an empty image (" +
                           std::to_string(image.width) + "x" + std::to_string(image.height) + ")");
    if (image.channels.empty()) throw RuntimeError(path.string() + ": image has no channels");
    const size_t n = static_cast<size_t>(image.width) * static_cast<size_t>(image.height);
    std::set<std::string> names;
    for (const auto& c : image.channels) {
        if (c.name.empty()) throw RuntimeError(path.string() + ": a channel has no name");
        if (!names.insert(c.name).second)
            throw RuntimeError(path.string() + ": channel '" + c.name + "' appears twice");
        if (c.pixels.size() != n)
            throw RuntimeError(path.string() + ": channel '" + c.name + "' holds " +
                               std::to_string(c.pixels.size()) + " values, expected " +
                               std::to_string(n));
    }
    const Imf::Header standard(1, 1);  // the attributes every EXR header holds
    std::set<std::string> attributes;
    auto checkName = [&](const std::string& name) {
        if (name.empty()) throw RuntimeError(path.string() + ": an attribute has no name");
        if (standard.find(name) != standard.end())
            throw RuntimeError(path.string() + ": attribute '" + name +
                               "' clashes with a standard EXR attribute");
        if (!attributes.insert(name).second)
            throw RuntimeError(path.string() + ": attribute '" + name + "' appears twice");
    };
    for (const auto& a : image.attributes) checkName(a.first);
    for (const auto& a : image.int_attributes) checkName(a.first);
    for (const auto& a : image.float_attributes) checkName(a.first);
    for (const auto& a : image.matrix_attributes) checkName(a.first);
}

Imath::M44f toM44f(const std::array<float, 16>& m) {
    Imath::M44f r;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) r[i][j] = m[static_cast<size_t>(4 * i + j)];
    return r;
}

std::array<float, 16> fromM44f(const Imath::M44f& m) {
    std::array<float, 16> r{};
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) r[static_cast<size_t>(4 * i + j)] = m[i][j];
    return r;
}

void writeExrFile(const std::filesystem::path& file, const Image& image) {
    Imf::Header header(image.width, image.height);
    header.compression() = Imf::ZIP_COMPRESSION;
    header.lineOrder() = Imf::INCREASING_Y;  // row 0 (top) first
    for (const auto& [name, value] : image.attributes)
        header.insert(name, Imf::StringAttribute(value));
    for (const auto& [name, value] : image.int_attributes)
        header.insert(name, Imf::IntAttribute(value));
    for (const auto& [name, value] : image.float_attributes)
        header.insert(name, Imf::FloatAttribute(value));
    for (const auto& [name, value] : image.matrix_attributes)
        header.insert(name, Imf::M44fAttribute(toM44f(value)));
    const Imath::Box2i window = header.dataWindow();
    const size_t width = static_cast<size_t>(image.width);
    // OpenEXR converts pixel types on input only: half channels need half buffers.
    std::vector<std::vector<Imath::half>> halves;
    halves.reserve(image.channels.size());
    Imf::FrameBuffer frame;
    for (const auto& c : image.channels) {
        if (c.type == PixelType::Half) {
            header.channels().insert(c.name, Imf::Channel(Imf::HALF));
            const auto& h = halves.emplace_back(c.pixels.begin(), c.pixels.end());
            frame.insert(c.name, Imf::Slice::Make(Imf::HALF, h.data(), window, sizeof(Imath::half),
                                                  sizeof(Imath::half) * width));
        } else {
            header.channels().insert(c.name, Imf::Channel(Imf::FLOAT));
            frame.insert(c.name, Imf::Slice::Make(Imf::FLOAT, c.pixels.data(), window,
                                                  sizeof(float), sizeof(float) * width));
        }
    }
    Imf::OutputFile out(file.c_str(), header);
    out.setFrameBuffer(frame);
    out.writePixels(image.height);
}

}  // namespace

void writeExr(const std::filesystem::path& path, const Image& image) {
    checkImage(path, image);
    useWorkerThreads();
    writeAtomically(path, [&](const std::filesystem::path& tmp) { writeExrFile(tmp, image); });
}

Image readExr(const std::filesystem::path& path) {
    const std::string where = path.string() + ": ";
    // A FIFO or device would block or never end: regular files only.
    if (const std::string why = notRegularFileReason(path); !why.empty())
        throw UnreadableImage(where + why);

    if (!std::ifstream(path, std::ios::binary))
        throw UnreadableImage(where + "cannot open: " + std::strerror(errno));
    bool tiled = false, deep = false, multiPart = false;
    if (!Imf::isOpenExrFile(path.c_str(), tiled, deep, multiPart))
        throw UnreadableImage(where + "not an OpenEXR file");
    if (deep) throw UnreadableImage(where + "deep OpenEXR images are not supported");

    useWorkerThreads();
    try {
        Imf::InputFile file(path.c_str());
        const Imf::Header& header = file.header();
        const Imath::Box2i window = header.dataWindow();
        const int64_t width = int64_t{window.max.x} - window.min.x + 1;
        const int64_t height = int64_t{window.max.y} - window.min.y + 1;
        if (width <= 0 || height <= 0 || width > INT32_MAX || height > INT32_MAX)
            throw UnreadableImage(where + "empty or invalid data window");

        std::vector<std::pair<std::string, PixelType>> channels;
        for (auto it = header.channels().begin(); it != header.channels().end(); ++it) {
            if (it.channel().xSampling != 1 || it.channel().ySampling != 1)
                throw UnreadableImage(where + "channel '" + it.name() +
                                      "' is subsampled, which is not supported");
            channels.emplace_back(
                it.name(), it.channel().type == Imf::HALF ? PixelType::Half : PixelType::Float);
        }
        std::stable_sort(channels.begin(), channels.end(), [](const auto& a, const auto& b) {
            return channelRank(a.first) < channelRank(b.first);
        });
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
        const size_t xStride = sizeof(float);
        const size_t yStride = sizeof(float) * static_cast<size_t>(width);
        constexpr int64_t kStripRows = 256;
        for (int64_t row = 0; nChannels > 0 && row < height; row += kStripRows) {
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
