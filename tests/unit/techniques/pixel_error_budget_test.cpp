// `adaptive`'s per-pixel error budget and shadow bits without GL: errors of cells that disagree
// at the same pixel add as a root sum of squares, splits go largest first until the target is
// met, and the bits' counts.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
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
    // pixel 3 is shadowed by no slot, so index() leaves it out. Word-major: pixels 0-3 of word
    // 0, then of word 1.
    ShadowBits bits;
    bits.pixels = 4;
    bits.words = 2;
    bits.scale = 4;
    bits.bits = {0b01u, 0b10u, 0b11u, 0u, 0u, 1u << 1, 0u, 0u};
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
    // Per group and per pair in one pass: (0, 1) disagrees at pixels 0 and 1, (1, 33) at 2.
    const std::vector<std::vector<std::pair<int, int>>> groups = {{{0, 1}}, {{1, 33}}};
    const Disagreements found = bits.disagreements(groups);
    EXPECT_EQ(found.where[0], (std::vector<std::uint32_t>{0, 1}));
    EXPECT_EQ(found.where[1], (std::vector<std::uint32_t>{2}));
    EXPECT_EQ(found.pairs, (std::vector<std::size_t>{2, 1}));
    EXPECT_EQ(found.anywhere, (std::vector<std::uint32_t>{0, 1, 2}));
    // Without the lists: the same counts.
    const Disagreements counted = bits.disagreements(groups, false);
    EXPECT_TRUE(counted.where[0].empty() && counted.where[1].empty());
    EXPECT_EQ(counted.pairs, found.pairs);
    EXPECT_EQ(counted.anywhere, found.anywhere);
}

// Random bits over 70 slots (3 words) of PIXELS pixels, a third of them in every slot's shadow
// or in none (the pass skips those); groups of up to three pairs, as a level's cells: the one
// pass finds what each pair tested alone finds.
void checkOnePassAgainstEveryPair(size_t pixels) {
    std::mt19937 rng(7);
    ShadowBits bits;
    bits.pixels = pixels;
    bits.words = 3;
    bits.bits.resize(bits.pixels * 3);
    for (size_t p = 0; p < bits.pixels; ++p)
        for (size_t k = 0; k < 3; ++k)
            bits.bits[k * bits.pixels + p] = p % 3 == 0   ? 0u
                                             : p % 3 == 1 ? std::uint32_t(rng())
                                             : k < 2      ? ~0u
                                                          : 0x3fu;  // slots 64-69
    bits.index();
    std::vector<std::vector<std::pair<int, int>>> groups(40);
    for (auto& g : groups)
        for (int n = 1 + int(rng() % 3); n > 0; --n)
            g.push_back({int(rng() % 70), int(rng() % 70)});
    const Disagreements found = bits.disagreements(groups);
    std::vector<std::uint32_t> anywhere;
    for (size_t p : bits.active)
        for (const auto& group : groups)
            if (std::any_of(group.begin(), group.end(), [&](std::pair<int, int> q) {
                    return bits.shadowed(p, q.first) != bits.shadowed(p, q.second);
                })) {
                anywhere.push_back(std::uint32_t(p));
                break;
            }
    EXPECT_EQ(found.anywhere, anywhere);
    for (size_t g = 0, j = 0; g < groups.size(); ++g) {
        std::vector<std::uint32_t> where;
        for (size_t p : bits.active) {
            bool any = false;
            for (auto [a, b] : groups[g]) any = any || bits.shadowed(p, a) != bits.shadowed(p, b);
            if (any) where.push_back(std::uint32_t(p));
        }
        EXPECT_EQ(found.where[g], where) << "group " << g;
        for (auto [a, b] : groups[g]) {
            size_t n = 0;
            for (size_t p = 0; p < bits.pixels; ++p)
                n += bits.shadowed(p, a) != bits.shadowed(p, b);
            EXPECT_EQ(found.pairs[j++], n) << "pair " << a << ", " << b;
        }
    }
}

TEST(ShadowBits, OnePassAgreesWithEveryPairTestedAlone) {
    checkOnePassAgainstEveryPair(500);
}

TEST(ShadowBits, ThreadsSplittingTheActivePixelsFindTheSame) {
    // 200k pixels (about 133k active): several chunks of the active pixels (parallel_chunks.h),
    // their counts added and lists joined in order.
    checkOnePassAgainstEveryPair(200003);
}

}  // namespace
}  // namespace penumbra::techniques::adaptive
