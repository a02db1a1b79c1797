// Contact sheets: the grid's geometry (near-square columns, gaps, label strips), an image
// scaled to fit its tile with its aspect kept and centred, and the PNG that reads back.
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include "renderer/core/error.h"
#include "renderer/output/contact_sheet.h"
#include "tests/unit/output/scratch_folder.h"

namespace penumbra::output {
namespace {

using testing::ScratchFolder;

TEST(ContactSheet, NearSquareGridWithGaps) {
    const SheetLayout l = planSheet(5, 0, 100, 50, {}, "");
    EXPECT_EQ(l.columns, 3);  // ceil(sqrt(5))
    EXPECT_EQ(l.rows, 2);
    EXPECT_EQ(l.gap, 2);
    EXPECT_EQ(l.label_height, 0);
    EXPECT_EQ(l.width(), 3 * 100 + 4 * 2);
    EXPECT_EQ(l.height(), 2 * 50 + 3 * 2);
    EXPECT_EQ(planSheet(5, 9, 100, 50, {}, "").columns, 5);  // never more columns than cells
    EXPECT_EQ(planSheet(1, 0, 100, 50, {}, "").columns, 1);
}

TEST(ContactSheet, LabelsShareOneFontSizeAndAreCutToFit) {
    const std::string font = findLabelFont("");  // DejaVuSans (fonts-dejavu-core)
    const SheetLayout l =
        planSheet(2, 0, 90, 90, {"short", "a label far too long for a 90-pixel tile"}, font);
    ASSERT_EQ(l.labels.size(), 2u);
    EXPECT_EQ(l.labels[0], "short");
    EXPECT_EQ(l.labels[1].substr(l.labels[1].size() - 3), "...");
    EXPECT_EQ(l.font_size, 9);  // shrunk as far as it goes before cutting
    EXPECT_GT(l.label_height, l.font_size);
    EXPECT_THROW(findLabelFont("/no/such/font.ttf"), InputError);
}

TEST(ContactSheet, ImageScaledToFitItsTileCentred) {
    ScratchFolder dir;
    ContactSheet sheet(planSheet(1, 0, 100, 50, {}, ""));
    DisplayImage white{10, 10, std::vector<float>(10 * 10 * 3, 1.0f)};
    sheet.place(0, white);  // 10x10 into 100x50: 50x50, 25 columns of background either side
    sheet.write(dir / "sheet.png");
    auto in = OIIO::ImageInput::open((dir / "sheet.png").string());
    ASSERT_TRUE(in) << OIIO::geterror();
    ASSERT_EQ(in->spec().width, 104);
    ASSERT_EQ(in->spec().height, 54);
    std::vector<unsigned char> px(104 * 54 * 3);
    ASSERT_TRUE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, px.data()));
    auto red = [&](int x, int y) { return px[static_cast<size_t>((y * 104 + x) * 3)]; };
    EXPECT_EQ(red(2 + 25, 2), 255);                     // the picture's first column
    EXPECT_EQ(red(2 + 74, 51), 255);                    // its last, bottom row
    EXPECT_LT(red(2 + 24, 20), 40);                     // background left of it
    EXPECT_LT(red(2 + 75, 20), 40);                     // and right of it
    EXPECT_LT(red(0, 0), 40);                           // the gap
    EXPECT_THROW(sheet.place(1, white), RuntimeError);  // no such cell
}

}  // namespace
}  // namespace penumbra::output
