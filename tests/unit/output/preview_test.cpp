// PNG preview and its tone curve: the PNG reads back (with OpenImageIO) as 8-bit RGB holding the
// tone-mapped values; the curve is monotonic, black at 0, white for large values.
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "renderer/core/error.h"
#include "renderer/output/preview.h"
#include "renderer/output/tone_map.h"
#include "tests/unit/output/scratch_folder.h"

namespace penumbra::output {
namespace {

using testing::ScratchFolder;

TEST(ToneMap, CurveIsMonotonicFromBlackToWhite) {
    EXPECT_EQ(toneMap(0.0f, 0.0f), 0.0f);
    EXPECT_EQ(toneMap(-1.0f, 0.0f), 0.0f);
    EXPECT_EQ(toneMap(std::numeric_limits<float>::quiet_NaN(), 0.0f), 0.0f);
    EXPECT_EQ(toneMap(std::numeric_limits<float>::infinity(), 0.0f), 1.0f);
    EXPECT_EQ(toneMap(1e30f, 0.0f), 1.0f);
    EXPECT_EQ(toneMap8(100.0f, 0.0f), 255);
    float previous = 0.0f;
    for (float x = 0.0f; x < 20.0f; x += 0.001f) {
        const float y = toneMap(x, 0.0f);
        ASSERT_GE(y, previous) << "at " << x;
        ASSERT_LE(y, 1.0f);
        previous = y;
    }
    // Strictly increasing where it has not yet saturated.
    EXPECT_LT(toneMap(0.1f, 0.0f), toneMap(0.2f, 0.0f));
    EXPECT_LT(toneMap(2.0f, 0.0f), toneMap(4.0f, 0.0f));
}

TEST(ToneMap, ExposureIsInStops) {
    for (float x : {0.01f, 0.18f, 0.5f, 1.0f}) {
        EXPECT_FLOAT_EQ(toneMap(x, 1.0f), toneMap(2.0f * x, 0.0f));
        EXPECT_FLOAT_EQ(toneMap(x, -2.0f), toneMap(0.25f * x, 0.0f));
    }
}

TEST(ToneMap, SrgbTransferMatchesTheStandard) {
    EXPECT_FLOAT_EQ(srgbEncode(0.0f), 0.0f);
    EXPECT_FLOAT_EQ(srgbEncode(1.0f), 1.0f);
    EXPECT_NEAR(srgbEncode(0.002f), 0.02584f, 1e-5);  // linear segment
    EXPECT_NEAR(srgbEncode(0.18f), 0.46135f, 1e-4);
    EXPECT_NEAR(filmicCurve(1.0f), 2.54f / 3.16f, 1e-6);
}

TEST(Preview, WritesAReadable8BitRgbPng) {
    ScratchFolder dir;
    Image image;
    image.width = 3;
    image.height = 2;
    image.add("R", PixelType::Half).pixels = {0, 0.18f, 1, 4, 100, -1};
    image.add("G", PixelType::Half).pixels = {0.5f, 0, 0, 0, 0, 0};
    image.add("B", PixelType::Half).pixels = {0, 0, 0, 0, 0, 2};
    image.add("A", PixelType::Half).pixels = {1, 1, 1, 1, 1, 1};
    const auto path = dir / "preview/frame.png";
    writePngPreview(path, image, 0.5f);
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"preview"});

    auto in = OIIO::ImageInput::open(path.string());
    ASSERT_TRUE(in) << OIIO::geterror();
    const OIIO::ImageSpec& spec = in->spec();
    EXPECT_EQ(std::string(in->format_name()), "png");
    EXPECT_EQ(spec.width, 3);
    EXPECT_EQ(spec.height, 2);
    ASSERT_EQ(spec.nchannels, 3);
    EXPECT_EQ(spec.format, OIIO::TypeDesc::UINT8);
    std::vector<unsigned char> pixels(3 * 2 * 3);
    ASSERT_TRUE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, pixels.data()));
    for (size_t i = 0; i < 6; ++i)
        for (size_t c = 0; c < 3; ++c)
            EXPECT_EQ(pixels[i * 3 + c], toneMap8(image.channels[c].pixels[i], 0.5f))
                << "pixel " << i << " channel " << c;
    EXPECT_EQ(pixels[0], 0);        // black stays black
    EXPECT_EQ(pixels[4 * 3], 255);  // 100 saturates (row 1, column 1)
}

TEST(Preview, NeedsRgb) {
    ScratchFolder dir;
    Image image;
    image.width = 1;
    image.height = 1;
    image.add("R", PixelType::Half);
    image.add("G", PixelType::Half);
    EXPECT_THROW(writePngPreview(dir / "a.png", image), InputError);
    EXPECT_TRUE(dir.entries().empty());
}

TEST(Preview, FailedWriteLeavesNothingBehind) {
    ScratchFolder dir;
    Image image;
    image.width = 1;
    image.height = 1;
    for (const char* name : {"R", "G", "B"}) image.add(name, PixelType::Half);
    std::filesystem::create_directories(dir / "taken.png/inside");
    EXPECT_THROW(writePngPreview(dir / "taken.png", image), RuntimeError);
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"taken.png"});
}

}  // namespace
}  // namespace penumbra::output
