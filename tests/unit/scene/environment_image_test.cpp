// Environment maps: .hdr and .exr read as linear RGB, rows top to bottom, grey replicated,
// and the refusals (wrong type, missing, too large, non-finite pixels).
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <cmath>

#include "renderer/scene/environment_image.h"
#include "scene_test_support.h"

namespace penumbra::scene {
namespace {

using test::expectMessage;
using test::inputErrorOf;

std::filesystem::path writeExr(const std::string& name, int width, int height, int channels,
                               const std::vector<float>& pixels) {
    const auto path = test::scratchDir() / name;
    auto out = OIIO::ImageOutput::create(path.string());
    EXPECT_TRUE(out);
    OIIO::ImageSpec spec(width, height, channels, OIIO::TypeDesc::FLOAT);
    EXPECT_TRUE(out->open(path.string(), spec));
    EXPECT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, pixels.data()));
    out->close();
    return path;
}

TEST(EnvironmentImage, ReadsHdrAndExrTopRowFirst) {
    // Fixtures: 8x4 vertical gradients from (4, 2, 1) at the top to (0, 0, 0.5) at the bottom.
    for (const char* name : {"sky.hdr", "sky.exr"}) {
        SCOPED_TRACE(name);
        const auto image = loadEnvironmentImage(test::dataDir() / name);
        ASSERT_EQ(image->width, 8);
        ASSERT_EQ(image->height, 4);
        ASSERT_EQ(image->rgb.size(), 8u * 4u * 3u);
        EXPECT_EQ(image->rgb[0], 4.0f);
        EXPECT_EQ(image->rgb[1], 2.0f);
        EXPECT_EQ(image->rgb[2], 1.0f);
        const std::size_t last = (3 * 8 + 7) * 3;
        EXPECT_EQ(image->rgb[last + 0], 0.0f);
        EXPECT_EQ(image->rgb[last + 2], 0.5f);
    }
}

TEST(EnvironmentImage, GreyIsReplicatedAndNegativesClamped) {
    const auto path = writeExr("grey.exr", 2, 1, 1, {0.25f, -3.0f});
    const auto image = loadEnvironmentImage(path);
    EXPECT_EQ(image->rgb, (std::vector<float>{0.25f, 0.25f, 0.25f, 0, 0, 0}));
    const auto rgba = writeExr("rgba.exr", 1, 1, 4, {1, 2, 3, 0.5f});
    EXPECT_EQ(loadEnvironmentImage(rgba)->rgb, (std::vector<float>{1, 2, 3}));
}

// A 2x1 half EXR of NAMES, pixel-interleaved PIXELS.
std::filesystem::path writeNamedExr(const std::string& file, std::vector<std::string> names,
                                    const std::vector<float>& pixels) {
    const auto path = test::scratchDir() / file;
    auto out = OIIO::ImageOutput::create(path.string());
    EXPECT_TRUE(out);
    OIIO::ImageSpec spec(2, 1, static_cast<int>(names.size()), OIIO::TypeDesc::HALF);
    spec.channelnames = std::move(names);
    EXPECT_TRUE(out->open(path.string(), spec));
    EXPECT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, pixels.data()));
    out->close();
    return path;
}

// An OpenEXR map is read by the project's own reader: R, G, B whatever the other channels and
// their order, half channels as float; with no plain R, G, B, a layer's (diffuse.R, ...), else
// the luminance Y as grey.
TEST(EnvironmentImage, ExrChannelsByNameAndHalf) {
    const auto plain = writeNamedExr("named.exr", {"Z", "B", "G", "R", "A"},
                                     {9, 0.5f, 0.25f, 2, 1, 9, 3, 4, 0.125f, 1});
    EXPECT_EQ(loadEnvironmentImage(plain)->rgb, (std::vector<float>{2, 0.25f, 0.5f, 0.125f, 4, 3}));
    const auto layer =
        writeNamedExr("layer.exr", {"Z", "specular.R", "diffuse.B", "diffuse.G", "diffuse.R"},
                      {9, 8, 0.5f, 0.25f, 2, 9, 8, 3, 4, 0.125f});
    EXPECT_EQ(loadEnvironmentImage(layer)->rgb, (std::vector<float>{2, 0.25f, 0.5f, 0.125f, 4, 3}));
    const auto luminance = writeNamedExr("ya.exr", {"A", "Y"}, {1, 0.5f, 1, 2});
    EXPECT_EQ(loadEnvironmentImage(luminance)->rgb,
              (std::vector<float>{0.5f, 0.5f, 0.5f, 2, 2, 2}));
}

TEST(EnvironmentImage, Refusals) {
    const auto nan = writeExr("nan.exr", 2, 1, 3, {1, 1, 1, 1, std::nanf(""), 1});
    expectMessage(inputErrorOf([&] { loadEnvironmentImage(nan); }),
                  nan.string() + ": non-finite pixel at (1, 0)");
    const auto wide = writeExr("wide.exr", kMaxEnvironmentSize + 1, 1, 1,
                               std::vector<float>(kMaxEnvironmentSize + 1, 1.0f));
    expectMessage(inputErrorOf([&] { loadEnvironmentImage(wide); }),
                  wide.string() + ": image too large (16385x1, limit 16384)");
    const auto missing = test::scratchDir() / "missing.hdr";
    expectMessage(inputErrorOf([&] { loadEnvironmentImage(missing); }),
                  missing.string() + ": no such file");
    const auto png = test::scratchDir() / "sky.png";
    expectMessage(inputErrorOf([&] { loadEnvironmentImage(png); }),
                  png.string() + ": expected an .exr or .hdr file");
    const auto junk = test::writeFile("junk.exr", "not an image at all");
    expectMessage(inputErrorOf([&] { loadEnvironmentImage(junk); }),
                  junk.string() + ": cannot read image: not an OpenEXR file");
    const auto dir = test::scratchDir() / "folder.exr";
    std::filesystem::create_directories(dir);
    expectMessage(inputErrorOf([&] { loadEnvironmentImage(dir); }), dir.string() + ": is a folder");
}

// A file is read by the reader its name says, or refused: a TIFF named .hdr is not an
// environment map. OpenImageIO's own open() tries every reader it has where the named one fails,
// which read such a file, and spent seconds on a damaged PNG (the fuzz corpus's
// truncated_text_chunk.png).
TEST(EnvironmentImage, AFileOfAnotherFormatThanItsNameIsRefused) {
    const auto tiff = test::scratchDir() / "sky_as_tiff.tif";
    {
        auto out = OIIO::ImageOutput::create(tiff.string());
        ASSERT_TRUE(out);
        const std::vector<float> pixels(2 * 3, 0.5f);
        ASSERT_TRUE(out->open(tiff.string(), OIIO::ImageSpec(2, 1, 3, OIIO::TypeDesc::FLOAT)));
        ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, pixels.data()));
        out->close();
    }
    const auto disguised = test::scratchDir() / "sky_as_tiff.hdr";
    std::filesystem::rename(tiff, disguised);
    expectMessage(inputErrorOf([&] { loadEnvironmentImage(disguised); }),
                  disguised.string() + ": cannot read image");
}

// An OpenEXR header attribute that declares more bytes than the file holds is refused before
// the decoder allocates it (a 1 KB file claiming 800 MB cost 840 MB and seconds).
TEST(EnvironmentImage, AnExrAttributeLargerThanTheFileIsRefused) {
    const std::string bytes = std::string("\x76\x2f\x31\x01\x02\x00\x00\x00", 8) +
                              std::string("Software\0string\0\x00\x00\x00\x30", 20) + "x";
    test::writeFile("claims.exr", bytes);
    const auto path = test::scratchDir() / "claims.exr";
    expectMessage(inputErrorOf([&] { loadEnvironmentImage(path); }),
                  path.string() + ": cannot read image: header attribute 'Software' declares");
}

TEST(EnvironmentImage, SceneNamesTheKeyAndPath) {
    nlohmann::json doc = test::minimalScene();
    doc["environment"] = {{"image", "junk.exr"}};
    const std::string junk = (test::scratchDir() / "junk.exr").string();
    test::writeFile("junk.exr", "not an image at all");
    expectMessage(inputErrorOf([&] { test::loadDoc(doc); }),
                  (test::scratchDir() / "scene.json").string() + ": environment.image: " + junk +
                      ": cannot read image");
    doc["environment"] = {{"image", (test::dataDir() / "sky.exr").string()}, {"intensity", -1}};
    expectMessage(inputErrorOf([&] { test::loadDoc(doc); }),
                  "environment.intensity: expected a number >= 0");
}

}  // namespace
}  // namespace penumbra::scene
