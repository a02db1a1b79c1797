// `adaptive`: the refinement rule driven by the error it removes (metric "error"): an estimate of
// the shadow-region visibility error each cell's corner samples leave, and the cells to split.
#pragma once

#include <cstddef>
#include <vector>

namespace penumbra::techniques::adaptive {

// Mean |error| of a cell's corner estimate at a pixel where its corners disagree, as a share of
// the cell's weight: a straight shadow edge at a uniformly random offset across the cell leaves
// |t - 1/2| on average, 1/4 (edges at other angles do not leave more).
inline constexpr double kDisagreementError = 0.25;

// The estimated contribution of a cell to the shadow-region MAE of visibility: the cell's share
// LIGHT_SHARE of the light, times kDisagreementError, times its DISAGREEING pixels over the
// SHADOWED pixels of the frame (0 when nothing is shadowed). Both counts are pixels of the same
// comparison view, so the ratio does not depend on the image size.
double cellError(double light_share, double disagreeing, double shadowed);

// The greedy choice, level by level, of the cells whose split removes the most estimated error,
// until the total estimate falls to a target: a split halves a cell's error (an edge crossing a
// cell crosses about half of its children).
class ErrorBudget {
public:
    explicit ErrorBudget(double target) : target_(target) {}

    // The measured ERRORS of this level's cells replace the estimates of the splits that made
    // them; returns the indices to split, largest error first, while the total is above target.
    // The others are settled (they stay leaves). Call refused() for a chosen cell not split.
    std::vector<size_t> choose(const std::vector<double>& errors);
    void refused(double error);
    // Settled errors plus half of every chosen split's: the error the refinement is expected
    // to leave.
    double estimate() const { return settled_ + pending_; }

private:
    double target_;
    double settled_ = 0;
    double pending_ = 0;
};

}  // namespace penumbra::techniques::adaptive
