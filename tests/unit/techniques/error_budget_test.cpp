// `adaptive`'s error-driven refinement rule without GL: the per-cell estimate (a ratio of pixel
// counts, so the image size cancels) and the greedy choice of splits against a target.
#include <gtest/gtest.h>

#include <vector>

#include "renderer/techniques/adaptive/error_budget.h"

namespace penumbra::techniques::adaptive {
namespace {

TEST(ErrorBudget, CellErrorIsARatioOfCountsTimesTheCellsShare) {
    EXPECT_DOUBLE_EQ(cellError(1.0, 100, 400), kDisagreementError * 0.25);
    // The same share of the shadow at 4x the pixels (twice the image side): the same estimate.
    EXPECT_DOUBLE_EQ(cellError(1.0, 400, 1600), cellError(1.0, 100, 400));
    // A quarter of the light carries a quarter of the error.
    EXPECT_DOUBLE_EQ(cellError(0.25, 100, 400), 0.25 * cellError(1.0, 100, 400));
    EXPECT_EQ(cellError(1.0, 0, 400), 0.0);
    EXPECT_EQ(cellError(1.0, 10, 0), 0.0);  // nothing shadowed: nothing to refine
    // A stride's estimates can put more disagreeing than shadowed pixels: never above the share.
    EXPECT_DOUBLE_EQ(cellError(1.0, 500, 400), kDisagreementError);
}

TEST(ErrorBudget, SplitsLargestFirstUntilTheTargetIsReached) {
    ErrorBudget budget(0.05);
    // Total 0.12: splitting 0.06 leaves 0.09, splitting 0.04 leaves 0.07, 0.015 leaves 0.0625,
    // 0.005 leaves 0.06 > target: all four go; the zero cell never does.
    auto chosen = budget.choose({0.015, 0.06, 0.0, 0.04, 0.005});
    EXPECT_EQ(chosen, (std::vector<size_t>{1, 3, 0, 4}));
    EXPECT_NEAR(budget.estimate(), 0.06, 1e-12);
    // The children measured: 0.03 in all, at most the target already: nothing more to split.
    chosen = budget.choose({0.02, 0.01});
    EXPECT_TRUE(chosen.empty());
    EXPECT_NEAR(budget.estimate(), 0.03, 1e-12);
}

TEST(ErrorBudget, StopsAsSoonAsTheEstimateMeetsTheTarget) {
    ErrorBudget budget(0.1);
    // Total 0.2: splitting 0.12 leaves 0.14, splitting 0.06 leaves 0.11, splitting 0.02 leaves
    // 0.10: done, and the 0.0 cell settles.
    auto chosen = budget.choose({0.02, 0.12, 0.06, 0.0});
    EXPECT_EQ(chosen, (std::vector<size_t>{1, 2, 0}));
    EXPECT_NEAR(budget.estimate(), 0.10, 1e-12);
    ErrorBudget loose(0.5);
    EXPECT_TRUE(loose.choose({0.02, 0.12, 0.06}).empty());
    EXPECT_NEAR(loose.estimate(), 0.2, 1e-12);
}

TEST(ErrorBudget, ARefusedSplitKeepsItsWholeError) {
    ErrorBudget budget(0.0);
    auto chosen = budget.choose({0.08, 0.04});
    ASSERT_EQ(chosen.size(), 2u);
    EXPECT_NEAR(budget.estimate(), 0.06, 1e-12);
    budget.refused(0.08);  // the map budget could not split it
    EXPECT_NEAR(budget.estimate(), 0.10, 1e-12);
}

}  // namespace
}  // namespace penumbra::techniques::adaptive
