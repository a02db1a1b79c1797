// OpenEXR writing through OpenEXR's Imf API: see exr.h. The image is checked first (sizes,
// unique names); half channels are converted to half buffers. Reading is in exr_read.cpp.
#include "renderer/output/exr.h"

#include <Imath/ImathBox.h>
#include <Imath/half.h>
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFloatAttribute.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfIntAttribute.h>
#include <OpenEXR/ImfMatrixAttribute.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStringAttribute.h>

#include <algorithm>
#include <cstdint>
#include <set>
#include <utility>

#include "renderer/core/atomic_file.h"
#include "renderer/core/error.h"
#include "renderer/output/exr_threads.h"
#include "renderer/output/half_bits.h"

namespace penumbra::output {

namespace {

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

Imf::Compression imfCompression(ExrCompression::Method method) {
    switch (method) {
        case ExrCompression::Method::None:
            return Imf::NO_COMPRESSION;
        case ExrCompression::Method::Rle:
            return Imf::RLE_COMPRESSION;
        case ExrCompression::Method::Zips:
            return Imf::ZIPS_COMPRESSION;
        case ExrCompression::Method::Zip:
            return Imf::ZIP_COMPRESSION;
        case ExrCompression::Method::Piz:
            return Imf::PIZ_COMPRESSION;
    }
    return Imf::ZIP_COMPRESSION;
}

constexpr std::pair<std::string_view, ExrCompression::Method> kMethods[] = {
    {"none", ExrCompression::Method::None},
    {"rle", ExrCompression::Method::Rle},
    {"zips", ExrCompression::Method::Zips},
    {"zip", ExrCompression::Method::Zip},
    {"piz", ExrCompression::Method::Piz}};

bool takesLevel(ExrCompression::Method m) {
    return m == ExrCompression::Method::Zip || m == ExrCompression::Method::Zips;
}

void writeExrFile(const std::filesystem::path& file, const Image& image,
                  const ExrCompression& compression) {
    Imf::Header header(image.width, image.height);
    header.compression() = imfCompression(compression.method);
    header.zipCompressionLevel() = compression.level;
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
    // OpenEXR converts pixel types on input only: half channels need half buffers (the
    // sequence's, when the image has some, so that they are reused frame after frame).
    PixelBuffers own;
    PixelBuffers& buffers = image.buffers ? *image.buffers : own;
    std::vector<std::vector<std::uint16_t>> halves;
    halves.reserve(image.channels.size());
    Imf::FrameBuffer frame;
    for (const auto& c : image.channels) {
        if (c.type == PixelType::Half) {
            header.channels().insert(c.name, Imf::Channel(Imf::HALF));
            auto& h = halves.emplace_back(buffers.takeHalves(c.pixels.size()));
            toHalfBits(c.pixels.data(), h.data(), c.pixels.size());
            frame.insert(c.name, Imf::Slice::Make(Imf::HALF, h.data(), window, sizeof(h[0]),
                                                  sizeof(h[0]) * width));
        } else {
            header.channels().insert(c.name, Imf::Channel(Imf::FLOAT));
            frame.insert(c.name, Imf::Slice::Make(Imf::FLOAT, c.pixels.data(), window,
                                                  sizeof(float), sizeof(float) * width));
        }
    }
    Imf::OutputFile out(file.c_str(), header);
    out.setFrameBuffer(frame);
    out.writePixels(image.height);
    for (auto& h : halves) buffers.give(std::move(h));
}

}  // namespace

std::optional<ExrCompression> parseExrCompression(std::string_view text) {
    const size_t colon = text.find(':');
    const std::string_view name = text.substr(0, colon);
    for (const auto& [known, method] : kMethods) {
        if (name != known) continue;
        ExrCompression c{method};
        if (colon == std::string_view::npos) return c;
        const std::string_view level = text.substr(colon + 1);
        if (!takesLevel(method) || level.size() != 1 || level[0] < '1' || level[0] > '9')
            return std::nullopt;
        c.level = level[0] - '0';
        return c;
    }
    return std::nullopt;
}

std::string exrCompressionName(const ExrCompression& compression) {
    std::string text = "zip";
    for (const auto& [name, method] : kMethods)
        if (method == compression.method) text = name;
    if (takesLevel(compression.method)) text += ':' + std::to_string(compression.level);
    return text;
}

void writeExr(const std::filesystem::path& path, const Image& image,
              const ExrCompression& compression) {
    checkImage(path, image);
    useExrWorkerThreads();
    writeAtomically(
        path, [&](const std::filesystem::path& tmp) { writeExrFile(tmp, image, compression); });
}

}  // namespace penumbra::output
