// EXR writing and reading: round trip of half and float channels, dotted names, attributes and
// row order (checked with OpenImageIO as an independent reader); unreadable files; atomicity.
#include <Imath/half.h>
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <array>
#include <cmath>
#include <cstring>
#include <fstream>
#include <stdexcept>

#include "renderer/core/atomic_file.h"
#include "renderer/core/error.h"
#include "renderer/output/exr.h"
#include "tests/unit/output/image_attribute.h"
#include "tests/unit/output/scratch_folder.h"

namespace penumbra::output {
namespace {

using testing::attribute;
using testing::ScratchFolder;

// A 5x3 image (non-square, so a transposed or flipped write shows) holding every kind of
// channel the renderer writes. Values differ per channel, column and row.
Image makeImage() {
    Image image;
    image.width = 5;
    image.height = 3;
    const std::pair<const char*, PixelType> channels[] = {
        {"R", PixelType::Half},   {"G", PixelType::Half},
        {"B", PixelType::Half},   {"A", PixelType::Half},
        {"Z", PixelType::Float},  {"P.X", PixelType::Float},
        {"N.X", PixelType::Half}, {"visibility", PixelType::Float},
        {"id", PixelType::Float}, {"adaptive.maps", PixelType::Float},
    };
    int k = 0;
    for (const auto& [name, type] : channels) {
        ImageChannel& c = image.add(name, type);
        for (int y = 0; y < image.height; ++y)
            for (int x = 0; x < image.width; ++x)
                c.pixels[static_cast<size_t>(y * image.width + x)] =
                    0.1f * static_cast<float>(k) + 0.01f * static_cast<float>(x) +
                    0.001f * static_cast<float>(y) + 1e-7f;
        ++k;
    }
    image.attributes = {{"penumbra/technique", "adaptive"},
                        {"penumbra/params", R"({"epsilon":0.01})"},
                        {"penumbra/scene", "scenes/bunny.json"}};
    return image;
}

float roundTripValue(PixelType type, float v) {
    return type == PixelType::Half ? static_cast<float>(Imath::half(v)) : v;
}

// The pixels of channel NAME; throws when it is missing (so a test fails instead of crashing).
const std::vector<float>& pixelsOf(const Image& image, const std::string& name) {
    if (const ImageChannel* c = image.find(name)) return c->pixels;
    throw std::runtime_error("no channel '" + name + "'");
}

TEST(Exr, RoundTripKeepsChannelsTypesValuesAndAttributes) {
    ScratchFolder dir;
    const Image written = makeImage();
    const auto path = dir / "sub/folder/frame.0001.exr";  // missing parents are created
    writeExr(path, written);
    ASSERT_TRUE(std::filesystem::exists(path));
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"sub"});

    const Image read = readExr(path);
    EXPECT_EQ(read.width, 5);
    EXPECT_EQ(read.height, 3);
    ASSERT_EQ(read.channels.size(), written.channels.size());
    for (const auto& w : written.channels) {
        SCOPED_TRACE(w.name);
        const ImageChannel* r = read.find(w.name);
        ASSERT_NE(r, nullptr);
        EXPECT_EQ(r->type, w.type);
        ASSERT_EQ(r->pixels.size(), w.pixels.size());
        for (size_t i = 0; i < w.pixels.size(); ++i)
            EXPECT_EQ(r->pixels[i], roundTripValue(w.type, w.pixels[i])) << "pixel " << i;
    }
    for (const auto& [key, value] : written.attributes) EXPECT_EQ(attribute(read, key), value);

    // R, G, B, A first, then the file's (alphabetical) order.
    std::vector<std::string> names;
    for (const auto& c : read.channels) names.push_back(c.name);
    EXPECT_EQ(names, (std::vector<std::string>{"R", "G", "B", "A", "N.X", "P.X", "Z",
                                               "adaptive.maps", "id", "visibility"}));
}

TEST(Exr, HalfChannelsAreStoredAsHalf) {
    ScratchFolder dir;
    Image image;
    image.width = 1;
    image.height = 1;
    image.add("R", PixelType::Half).pixels[0] = 0.1f;
    image.add("Z", PixelType::Float).pixels[0] = 0.1f;
    writeExr(dir / "a.exr", image);
    const Image read = readExr(dir / "a.exr");
    EXPECT_NE(pixelsOf(read, "R")[0], 0.1f);  // 0.1 is not a half
    EXPECT_EQ(pixelsOf(read, "R")[0], static_cast<float>(Imath::half(0.1f)));
    EXPECT_EQ(pixelsOf(read, "Z")[0], 0.1f);
}

// Every method of --exr-compression is lossless: the pixels read back (through OpenImageIO, an
// independent reader) are the ones written, and the header names the method.
TEST(Exr, EveryCompressionReadsBackTheSamePixels) {
    ScratchFolder dir;
    Image written = makeImage();
    written.width = 64;  // a few blocks of rows for zip's 16-row blocks
    written.height = 40;
    for (auto& c : written.channels) {
        c.pixels.resize(static_cast<size_t>(written.width * written.height));
        for (size_t i = 0; i < c.pixels.size(); ++i)
            c.pixels[i] = roundTripValue(c.type, std::sin(0.37f * static_cast<float>(i)) * 3.0f);
    }
    const std::pair<const char*, const char*> methods[] = {
        {"zip", "zip"}, {"zip:1", "zip"}, {"zip:9", "zip"}, {"zips:1", "zips"},
        {"rle", "rle"}, {"none", "none"}, {"piz", "piz"}};
    for (const auto& [text, header] : methods) {
        SCOPED_TRACE(text);
        const auto compression = parseExrCompression(text);
        ASSERT_TRUE(compression);
        EXPECT_EQ(exrCompressionName(*compression).substr(0, std::string(header).size()), header);
        const auto path = dir / (std::string(header) + "_" + text[std::strlen(text) - 1] + ".exr");
        writeExr(path, written, *compression);
        auto in = OIIO::ImageInput::open(path.string());
        ASSERT_TRUE(in) << OIIO::geterror();
        const OIIO::ImageSpec& spec = in->spec();
        EXPECT_EQ(spec.get_string_attribute("compression"), header);
        std::vector<float> pixels(static_cast<size_t>(spec.width * spec.height * spec.nchannels));
        ASSERT_TRUE(in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, pixels.data()));
        for (const auto& w : written.channels) {
            const int c = spec.channelindex(w.name);
            ASSERT_GE(c, 0) << w.name;
            for (size_t i = 0; i < w.pixels.size(); ++i)
                ASSERT_EQ(pixels[i * static_cast<size_t>(spec.nchannels) + static_cast<size_t>(c)],
                          w.pixels[i])
                    << w.name << " pixel " << i;
        }
    }
}

TEST(Exr, CompressionNamesParseAndPrintBack) {
    for (const char* text : {"zip:1", "zip:4", "zip:9", "zips:1", "zips:6", "rle", "none", "piz"})
        EXPECT_EQ(exrCompressionName(parseExrCompression(text).value()), text);
    EXPECT_EQ(parseExrCompression("zip"), (ExrCompression{ExrCompression::Method::Zip, 4}));
    EXPECT_EQ(parseExrCompression("zips")->level, 4);
    EXPECT_EQ(ExrCompression{}, parseExrCompression("zips"));  // the default
    for (const char* bad : {"", "ZIP", "zip:", "zip:0", "zip:10", "zip:x", "rle:1", "piz:2", "dwaa",
                            "b44", "pxr24", "zip:1:2", " zip"})
        EXPECT_FALSE(parseExrCompression(bad)) << "'" << bad << "'";
}

TEST(Exr, RowZeroIsTheTopRowForOtherReaders) {
    ScratchFolder dir;
    const Image written = makeImage();
    const auto path = dir / "rows.exr";
    writeExr(path, written);

    auto in = OIIO::ImageInput::open(path.string());
    ASSERT_TRUE(in) << OIIO::geterror();
    const OIIO::ImageSpec& spec = in->spec();
    EXPECT_EQ(spec.width, 5);
    EXPECT_EQ(spec.height, 3);
    EXPECT_EQ(spec.get_string_attribute("compression"), "zips");  // the default
    EXPECT_EQ(spec.get_string_attribute("penumbra/technique"), "adaptive");
    std::vector<float> pixels(static_cast<size_t>(spec.width * spec.height * spec.nchannels));
    ASSERT_TRUE(in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, pixels.data()));
    for (const auto& w : written.channels) {
        SCOPED_TRACE(w.name);
        const int c = spec.channelindex(w.name);
        ASSERT_GE(c, 0);
        EXPECT_EQ(spec.channelformat(c),
                  w.type == PixelType::Half ? OIIO::TypeDesc::HALF : OIIO::TypeDesc::FLOAT);
        for (int y = 0; y < 3; ++y)
            for (int x = 0; x < 5; ++x)
                EXPECT_EQ(pixels[static_cast<size_t>((y * 5 + x) * spec.nchannels + c)],
                          roundTripValue(w.type, w.pixels[static_cast<size_t>(y * 5 + x)]))
                    << x << "," << y;
    }
}

TEST(Exr, TypedAttributesKeepTheirTypeForOtherReaders) {
    ScratchFolder dir;
    Image image = makeImage();
    image.int_attributes = {{"penumbra/frame", 42}};
    image.float_attributes = {{"penumbra/camera/fov_y", 37.5f}};
    std::array<float, 16> m{};
    for (size_t i = 0; i < 16; ++i) m[i] = static_cast<float>(i) + 0.5f;
    image.matrix_attributes = {{"worldToNDC", m}};
    const auto path = dir / "typed.exr";
    writeExr(path, image);

    auto in = OIIO::ImageInput::open(path.string());
    ASSERT_TRUE(in) << OIIO::geterror();
    const OIIO::ImageSpec& spec = in->spec();
    const OIIO::ParamValue* frame = spec.find_attribute("penumbra/frame");
    ASSERT_NE(frame, nullptr);
    EXPECT_EQ(frame->type(), OIIO::TypeInt);
    EXPECT_EQ(frame->get_int(), 42);
    const OIIO::ParamValue* fov = spec.find_attribute("penumbra/camera/fov_y");
    ASSERT_NE(fov, nullptr);
    EXPECT_EQ(fov->type(), OIIO::TypeFloat);
    EXPECT_EQ(fov->get_float(), 37.5f);
    const OIIO::ParamValue* ndc = spec.find_attribute("worldToNDC");
    ASSERT_NE(ndc, nullptr);
    EXPECT_EQ(ndc->type(), OIIO::TypeMatrix44);
    const auto* values = static_cast<const float*>(ndc->data());
    for (size_t i = 0; i < 16; ++i) EXPECT_EQ(values[i], m[i]) << i;  // row-major, as Imath

    const Image read = readExr(path);
    EXPECT_EQ(read.int_attributes, image.int_attributes);
    EXPECT_EQ(read.float_attributes, image.float_attributes);
    EXPECT_EQ(read.matrix_attributes, image.matrix_attributes);

    image.float_attributes = {{"penumbra/frame", 1.0f}};  // a name given twice is refused
    EXPECT_THROW(writeExr(dir / "twice.exr", image), RuntimeError);
}

TEST(Exr, OverwritesAnExistingFile) {
    ScratchFolder dir;
    Image image;
    image.width = 2;
    image.height = 2;
    image.add("Z", PixelType::Float).pixels = {1, 2, 3, 4};
    writeExr(dir / "a.exr", image);
    image.channels[0].pixels = {5, 6, 7, 8};
    writeExr(dir / "a.exr", image);
    EXPECT_EQ(pixelsOf(readExr(dir / "a.exr"), "Z"), (std::vector<float>{5, 6, 7, 8}));
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"a.exr"});
}

// Limits: the first channels in reading order only, and a side over the limit refused from
// the header (the environment and budget maps' checks).
TEST(Exr, ReadLimitsChannelsAndSize) {
    ScratchFolder dir;
    const Image image = makeImage();
    writeExr(dir / "a.exr", image);
    const Image rgb = readExr(dir / "a.exr", {.channels = 3});
    ASSERT_EQ(rgb.channels.size(), 3u);
    EXPECT_EQ(rgb.channels[0].name, "R");
    EXPECT_EQ(rgb.channels[2].name, "B");
    EXPECT_EQ(rgb.channels[1].pixels, pixelsOf(readExr(dir / "a.exr"), "G"));
    EXPECT_EQ(readExr(dir / "a.exr", {.channels = 0}).channels.size(), image.channels.size());
    EXPECT_EQ(readExr(dir / "a.exr", {.max_side = 5}).width, 5);
    try {
        readExr(dir / "a.exr", {.max_side = 4});
        FAIL() << "no exception";
    } catch (const ImageTooLarge& e) {
        EXPECT_EQ(std::string(e.what()),
                  (dir / "a.exr").string() + ": image too large (5x3, limit 4)");
    }
}

TEST(Exr, ReadMissingFileThrowsUnreadable) {
    ScratchFolder dir;
    try {
        readExr(dir / "nope.exr");
        FAIL() << "no exception";
    } catch (const UnreadableImage& e) {
        EXPECT_NE(std::string(e.what()).find("nope.exr"), std::string::npos) << e.what();
    }
    EXPECT_THROW(readExr(dir.path()), UnreadableImage);  // a folder
}

TEST(Exr, ReadTextFileThrowsUnreadable) {
    ScratchFolder dir;
    std::ofstream(dir / "text.exr") << "this is not an image\n";
    EXPECT_THROW(readExr(dir / "text.exr"), UnreadableImage);
    std::ofstream(dir / "empty.exr").close();
    EXPECT_THROW(readExr(dir / "empty.exr"), UnreadableImage);
}

TEST(Exr, ReadTruncatedFileThrowsUnreadable) {
    ScratchFolder dir;
    Image image;
    image.width = 64;
    image.height = 64;
    ImageChannel& c = image.add("Z", PixelType::Float);
    uint32_t state = 12345;  // noise, so ZIP cannot shrink the pixel data to nothing
    for (float& v : c.pixels) {
        state = state * 1664525u + 1013904223u;
        v = static_cast<float>(state >> 8) / 16777216.0f;
    }
    const auto path = dir / "truncated.exr";
    writeExr(path, image);
    const auto size = std::filesystem::file_size(path);
    ASSERT_GT(size, 4000u);
    for (auto keep : {size / 2, size - 7, uintmax_t{400}, uintmax_t{20}}) {
        SCOPED_TRACE(keep);
        writeExr(path, image);
        std::filesystem::resize_file(path, keep);
        EXPECT_THROW(readExr(path), UnreadableImage);
    }
}

// A header attribute that declares more bytes than the file holds is refused before OpenEXR
// allocates it (a fuzzing finding: a 1 KB file claiming an 800 MB string took 840 MB and, on a
// loaded machine, over 10 s). The attribute is named in the message.
TEST(Exr, AnAttributeLargerThanTheFileIsRefusedUnread) {
    ScratchFolder dir;
    std::string bytes("\x76\x2f\x31\x01\x02\x00\x00\x00", 8);
    bytes += std::string("Software\0string\0", 16);
    bytes += std::string("\x00\x00\x00\x30", 4);  // 805306368 bytes
    bytes += "penumbra";
    std::ofstream(dir / "claims.exr", std::ios::binary) << bytes;
    try {
        readExr(dir / "claims.exr");
        FAIL() << "no exception";
    } catch (const UnreadableImage& e) {
        EXPECT_NE(std::string(e.what()).find("'Software' declares 805306368 bytes"),
                  std::string::npos)
            << e.what();
    }
}

TEST(Exr, FailedWriteLeavesNothingBehind) {
    ScratchFolder dir;
    Image image;
    image.width = 2;
    image.height = 1;
    image.add("R", PixelType::Half);

    // The final name is a folder: refused before the temporary file is written.
    std::filesystem::create_directories(dir / "taken.exr/inside");
    EXPECT_THROW(writeExr(dir / "taken.exr", image), RuntimeError);
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"taken.exr"});
    EXPECT_TRUE(std::filesystem::is_directory(dir / "taken.exr"));

    // A header attribute OpenEXR refuses: the write fails before any pixel.
    Image clash = image;
    clash.attributes = {{"compression", "none"}};
    EXPECT_THROW(writeExr(dir / "clash.exr", clash), RuntimeError);
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"taken.exr"});

    // The parent is a file, so the folder cannot be created.
    std::ofstream(dir / "file").close();
    EXPECT_THROW(writeExr(dir / "file/a.exr", image), RuntimeError);
    EXPECT_EQ(dir.entries(), (std::vector<std::string>{"file", "taken.exr"}));
}

TEST(Exr, WriteIntoUnwritableFolderThrowsAndLeavesNothing) {
    ScratchFolder dir;
    Image image;
    image.width = 2;
    image.height = 1;
    image.add("R", PixelType::Half);
    if (::geteuid() != 0) {
        const auto locked = dir / "locked";
        std::filesystem::create_directories(locked);
        std::filesystem::permissions(
            locked, std::filesystem::perms::owner_read | std::filesystem::perms::owner_exec);
        EXPECT_THROW(writeExr(locked / "a.exr", image), RuntimeError);
        std::filesystem::permissions(locked, std::filesystem::perms::owner_all);
        EXPECT_TRUE(std::filesystem::is_empty(locked));
    }
    // Not even root can create files in /proc.
    if (std::filesystem::exists("/proc/self")) {
        const std::filesystem::path path = "/proc/penumbra-output-test.exr";
        EXPECT_THROW(writeExr(path, image), RuntimeError);
        EXPECT_FALSE(std::filesystem::exists(path));
        EXPECT_FALSE(std::filesystem::exists(temporaryPathFor(path)));
    }
}

TEST(Exr, WriteRejectsMalformedImages) {
    ScratchFolder dir;
    Image empty;
    EXPECT_THROW(writeExr(dir / "a.exr", empty), RuntimeError);
    Image wrongSize;
    wrongSize.width = 2;
    wrongSize.height = 2;
    wrongSize.add("R", PixelType::Half).pixels.resize(3);
    EXPECT_THROW(writeExr(dir / "a.exr", wrongSize), RuntimeError);
    Image twice;
    twice.width = 1;
    twice.height = 1;
    twice.add("R", PixelType::Half);
    twice.add("R", PixelType::Float);
    EXPECT_THROW(writeExr(dir / "a.exr", twice), RuntimeError);
    EXPECT_TRUE(dir.entries().empty());
}

}  // namespace
}  // namespace penumbra::output
