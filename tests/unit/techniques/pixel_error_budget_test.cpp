// `adaptive`'s per-pixel error budget and shadow bits without GL: errors of cells that disagree
// at the same pixel add as a root sum of squares, splits go largest first until the target is
// met, and the bits' counts.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "renderer/techniques/adaptive/pixel_error_budget.h"
#include "renderer/techniques/adaptive/shadow_bits.h"

namespace penumbra::techniques::adaptive {
namespace {

using Pixels = std::vector<std::vector<std::uint32_t>>;

TEST(PixelErrorBudget, CellsAtOnePixelAddAsARootSumOfSquares) {
    // Four pixels, each counting 1/4 of the shadowed area. Two cells of error 0.03 and 0.04
    // disagree at pixel 0: sqrt(0.03^2 + 0.04^2) = 0.05 there, not 0.07; a third of 0.02 at
    // pixel 1. The frame: (0.05 + 0.02) / 4.
    PixelErrorBudget budget(1.0, 4, 0.25);
    EXPECT_TRUE(budget.choose({0.03, 0.04, 0.02}, Pixels{{0}, {0}, {1}}).empty());
    EXPECT_NEAR(budget.estimate(), (0.05 + 0.02) / 4, 1e-12);
}

TEST(PixelErrorBudget, SplitsLargestFirstUntilTheTargetIsMet) {
    // One pixel counts the whole shadow. Cell 0 (0.1 at pixels 0, 1) and cell 1 (0.1 at pixel
    // 2) and cell 2 (0.01 at pixel 3): 0.31 in all. Splitting cell 0 (the most error x pixels)
    // leaves 0.1 / sqrt(8) at its pixels: 0.0707 + 0.1 + 0.01 = 0.181 <= 0.2: done.
    PixelErrorBudget budget(0.2, 4, 1.0);
    auto chosen = budget.choose({0.1, 0.1, 0.01}, Pixels{{0, 1}, {2}, {3}});
    EXPECT_EQ(chosen, (std::vector<size_t>{0}));
    EXPECT_NEAR(budget.estimate(), 2 * 0.1 / std::sqrt(8.0) + 0.1 + 0.01, 1e-12);
    // Its children measured: one of 0.025 at pixel 0, the pending estimate replaced.
    EXPECT_TRUE(budget.choose({0.025, 0.0, 0.0, 0.0}, Pixels{{0}, {}, {}, {}}).empty());
    EXPECT_NEAR(budget.estimate(), 0.025 + 0.1 + 0.01, 1e-12);
}

TEST(PixelErrorBudget, ARefusedSplitKeepsItsWholeError) {
    PixelErrorBudget budget(0.0, 2, 1.0);
    auto chosen = budget.choose({0.08, 0.04}, Pixels{{0}, {1}});
    ASSERT_EQ(chosen.size(), 2u);
    EXPECT_NEAR(budget.estimate(), (0.08 + 0.04) / std::sqrt(8.0), 1e-12);
    budget.refused(0);  // the map budget could not split it
    EXPECT_NEAR(budget.estimate(), 0.08 + 0.04 / std::sqrt(8.0), 1e-12);
}

TEST(PixelErrorBudget, NothingShadowedNothingToSplit) {
    PixelErrorBudget budget(0.0, 2, 0.0);  // per-pixel weight 0: no shadowed pixel
    EXPECT_TRUE(budget.choose({0.25}, Pixels{{0, 1}}).empty());
    EXPECT_EQ(budget.estimate(), 0.0);
}

TEST(ShadowBits, CountsAndDisagreements) {
    // Four pixels, two words each (slot 33 in the second word), every pixel standing for 4;
    // pixel 3 is shadowed by no slot, so index() leaves it out.
    ShadowBits bits;
    bits.pixels = 4;
    bits.words = 2;
    bits.scale = 4;
    bits.bits = {0b01u, 0u, 0b10u, 1u << 1, 0b11u, 0u, 0u, 0u};
    bits.index();
    EXPECT_EQ(bits.active, (std::vector<std::uint32_t>{0, 1, 2}));
    EXPECT_TRUE(bits.shadowed(0, 0));
    EXPECT_TRUE(bits.shadowed(1, 33));
    EXPECT_FALSE(bits.shadowed(2, 33));
    EXPECT_EQ(bits.anyShadowed(std::vector{0}), 8.0);      // pixels 0 and 2
    EXPECT_EQ(bits.anyShadowed(std::vector{33}), 4.0);     // pixel 1
    EXPECT_EQ(bits.anyShadowed(std::vector{0, 1}), 12.0);  // all three
    const std::vector<std::pair<int, int>> pairs = {{0, 1}};
    EXPECT_EQ(bits.disagreeing(pairs), (std::vector<std::uint32_t>{0, 1}));
    const std::vector<std::pair<int, int>> two = {{0, 1}, {1, 33}};
    EXPECT_EQ(bits.disagreeing(two), (std::vector<std::uint32_t>{0, 1, 2}));
}

}  // namespace
}  // namespace penumbra::techniques::adaptive
