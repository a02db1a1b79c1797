// `adaptive`: the error-driven refinement rule on per-pixel data (metric "error" on shadow
// bits): each cell's error where its corners disagree, combined per pixel as independent errors.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace penumbra::techniques::adaptive {

// The variance a split leaves of its cell's at a pixel: an edge crossing the cell crosses about
// 2 of its 4 children, each of a quarter of its weight: 2 x (1/4)^2 of the cell's squared error.
inline constexpr double kSplitVariance = 1.0 / 8.0;

// The estimate's scale to the measured error: uncalibrated, it was 1.34 to 1.47 times the
// receivers' shadow-region MAE against `exact` on conformance scenes (scripts/adaptive-estimate;
// errors of nearby pixels are not independent, and an edge near a corner errs less than 1/4).
inline constexpr double kErrorCalibration = 1.0 / 1.38;

// The greedy choice, level by level, of the cells to split until the frame's estimated
// shadow-region error falls to a target. A cell of share A of the light whose corners disagree
// at a pixel leaves A / 4 there (kDisagreementError); the jittered corners of different cells
// err independently, so a pixel's errors add as a root sum of squares, not as a sum (which
// overestimates a pixel crossed by many cells' edges: bar_grid's thin bars). The frame's error
// is the sum over pixels of that root, times PER_PIXEL (the stride's pixels over the shadowed
// pixels, so that the image size cancels).
class PixelErrorBudget {
public:
    PixelErrorBudget(double target, size_t pixels, double per_pixel);

    // This level's cells: ERRORS (A / 4 each) at the pixels WHERE (indices) their corners
    // disagree, replacing the estimates of the splits that made them. Returns the cells to
    // split, the largest error x pixels first, while the estimate is above the target; the
    // others are settled (they stay leaves). Call refused() for a chosen cell not split.
    std::vector<size_t> choose(const std::vector<double>& errors,
                               const std::vector<std::vector<std::uint32_t>>& where);
    void refused(size_t cell);
    // The error the refinement is expected to leave.
    double estimate() const { return total_; }

private:
    // Adds DELTA to pixel P's variance, keeping total_.
    void add(std::uint32_t p, double delta);

    double target_, per_pixel_;
    double total_ = 0;
    std::vector<double> variance_;  // per pixel: settled cells' and pending splits'
    std::vector<double> errors_;    // of the last choose()
    std::vector<std::vector<std::uint32_t>> where_;
};

}  // namespace penumbra::techniques::adaptive
