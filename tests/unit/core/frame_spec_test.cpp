// Frame specs: every form PRODUCT.md names, and every rejection.
#include <gtest/gtest.h>

#include "renderer/core/error.h"
#include "renderer/core/frame_spec.h"

using penumbra::InputError;
using penumbra::parseFrameSpec;

TEST(FrameSpec, SingleFrame) {
    EXPECT_EQ(parseFrameSpec("7", "--frames"), std::vector<int>{7});
}

TEST(FrameSpec, Range) {
    auto f = parseFrameSpec("1-120", "--frames");
    ASSERT_EQ(f.size(), 120u);
    EXPECT_EQ(f.front(), 1);
    EXPECT_EQ(f.back(), 120);
}

TEST(FrameSpec, RangeWithStep) {
    EXPECT_EQ(parseFrameSpec("1-10:4", "--frames"), (std::vector<int>{1, 5, 9}));
}

TEST(FrameSpec, MixedListSortedAndDeduplicated) {
    EXPECT_EQ(parseFrameSpec("9-13:2, 1-3,5,2", "--frames"),
              (std::vector<int>{1, 2, 3, 5, 9, 11, 13}));
}

TEST(FrameSpec, NegativeFrames) {
    EXPECT_EQ(parseFrameSpec("-2--1", "--frames"), (std::vector<int>{-2, -1}));
}

TEST(FrameSpec, Rejections) {
    for (const char* bad : {"", " ", "a", "1-", "-", "3-1", "1-5:0", "1-5:-1", "1,,2", "1:2",
                            "1-5:x", "1.5", "99999999999", "1-2-3"}) {
        try {
            parseFrameSpec(bad, "--frames");
            ADD_FAILURE() << "accepted '" << bad << "'";
        } catch (const InputError& e) {
            EXPECT_EQ(std::string(e.what()).rfind("--frames: ", 0), 0u) << e.what();
        }
    }
}
