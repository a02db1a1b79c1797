// compare's --diff .png heatmap: the default scale is the largest finite difference, the image
// reads back (with OpenImageIO) as the heatmap over a colour bar that ramps from 0 to the scale.
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <limits>

#include "renderer/core/error.h"
#include "renderer/output/heatmap.h"
#include "tests/unit/output/scratch_folder.h"

namespace penumbra::output {
namespace {

using testing::ScratchFolder;

// A 20x4 difference image: channel R rises along x (0 .. 0.19), G holds 0.5 at (3, 0) and an
// infinite difference at (4, 0).
Image makeDifference() {
    Image d;
    d.width = 20;
    d.height = 4;
    // add() returns references into d.channels: reserve so that none moves while held.
    d.channels.reserve(2);
    auto& r = d.add("R", PixelType::Float);
    auto& g = d.add("G", PixelType::Float);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 20; ++x) r.pixels[static_cast<size_t>(y * 20 + x)] = 0.01f * x;
    g.pixels[3] = 0.5f;
    g.pixels[4] = std::numeric_limits<float>::infinity();
    return d;
}

TEST(Heatmap, DefaultScaleIsTheLargestFiniteDifference) {
    EXPECT_FLOAT_EQ(defaultDifferenceScale(makeDifference()), 0.5f);
    Image zero = makeDifference();
    for (auto& c : zero.channels) std::fill(c.pixels.begin(), c.pixels.end(), 0.0f);
    EXPECT_EQ(defaultDifferenceScale(zero), 1.0f);  // nothing differs: any scale draws black
}

TEST(Heatmap, PngHoldsTheLargestChannelAndAColourBar) {
    ScratchFolder dir;
    const Image d = makeDifference();
    writeDifferenceHeatmap(dir / "heat.png", d, 0.5f);
    auto in = OIIO::ImageInput::open((dir / "heat.png").string());
    ASSERT_TRUE(in) << OIIO::geterror();
    const OIIO::ImageSpec& spec = in->spec();
    ASSERT_EQ(spec.width, 20);
    ASSERT_EQ(spec.height, 4 + colourBarRows(4));
    ASSERT_EQ(spec.nchannels, 3);
    std::vector<unsigned char> px(static_cast<size_t>(spec.width * spec.height * 3));
    ASSERT_TRUE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, px.data()));
    auto at = [&](int x, int y) {
        const unsigned char* p = &px[static_cast<size_t>((y * spec.width + x) * 3)];
        return std::vector<int>{p[0], p[1], p[2]};
    };
    unsigned char rgb[3];
    auto colour = [&](float t) {
        heatColour(t, rgb);
        return std::vector<int>{rgb[0], rgb[1], rgb[2]};
    };
    EXPECT_EQ(at(0, 0), colour(0.0f));
    EXPECT_EQ(at(10, 1), colour(0.1f / 0.5f));  // R alone
    EXPECT_EQ(at(3, 0), colour(1.0f));          // G's 0.5 beats R's 0.03: the scale, white
    EXPECT_EQ(at(4, 0), colour(1.0f));          // an infinite difference is white too
    EXPECT_EQ(at(4, 1), colour(0.04f / 0.5f));
    const int bar = 4 + 2;  // two dark rows separate the bar from the image
    EXPECT_EQ(at(0, bar), colour(0.0f));
    EXPECT_EQ(at(19, bar), colour(1.0f));
    EXPECT_EQ(at(19, spec.height - 1), colour(1.0f));

    EXPECT_THROW(writeDifferenceHeatmap(dir / "bad.png", d, 0.0f), RuntimeError);
}

TEST(Heatmap, SweepHeatmapHasTheSameColourBar) {
    ScratchFolder dir;
    Image ref, test;
    for (Image* im : {&ref, &test}) {
        im->width = 20;
        im->height = 4;
        im->add("visibility", PixelType::Float);
    }
    test.channels[0].pixels[0] = 0.25f;  // the full scale: white
    writeErrorHeatmap(dir / "error.png", ref, test, "visibility", 0.25f);
    auto in = OIIO::ImageInput::open((dir / "error.png").string());
    ASSERT_TRUE(in) << OIIO::geterror();
    const OIIO::ImageSpec& spec = in->spec();
    ASSERT_EQ(spec.width, 20);
    ASSERT_EQ(spec.height, 4 + colourBarRows(4));
    std::vector<unsigned char> px(static_cast<size_t>(spec.width * spec.height * 3));
    ASSERT_TRUE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, px.data()));
    unsigned char white[3], black[3];
    heatColour(1.0f, white);
    heatColour(0.0f, black);
    auto is = [&](int x, int y, const unsigned char* rgb) {
        const unsigned char* p = &px[static_cast<size_t>((y * spec.width + x) * 3)];
        return p[0] == rgb[0] && p[1] == rgb[1] && p[2] == rgb[2];
    };
    EXPECT_TRUE(is(0, 0, white));
    EXPECT_TRUE(is(1, 0, black));
    EXPECT_TRUE(is(0, 4 + 2, black));   // the bar, after 2 dark rows: 0 at the left
    EXPECT_TRUE(is(19, 4 + 2, white));  // the scale at the right
}

}  // namespace
}  // namespace penumbra::output
