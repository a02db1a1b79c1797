// `adaptive`: the per-pixel error-driven refinement rule; see pixel_error_budget.h.
#include "renderer/techniques/adaptive/pixel_error_budget.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace penumbra::techniques::adaptive {

PixelErrorBudget::PixelErrorBudget(double target, size_t pixels, double per_pixel)
    : target_(target), per_pixel_(per_pixel), variance_(pixels, 0.0) {}

void PixelErrorBudget::add(std::uint32_t p, double delta) {
    double& v = variance_[p];
    const double before = std::sqrt(v);
    v += delta;
    if (v < 1e-9 * std::fabs(delta)) v = 0;  // what cancels (a pending split) leaves no residue
    total_ += per_pixel_ * (std::sqrt(v) - before);
}

std::vector<size_t> PixelErrorBudget::choose(const std::vector<double>& errors,
                                             const std::vector<std::vector<std::uint32_t>>& where) {
    // The splits that made these cells leave their pending share: the children's own replace it.
    for (size_t i = 0; i < errors_.size(); ++i)
        for (std::uint32_t p : where_[i]) add(p, -kSplitVariance * errors_[i] * errors_[i]);
    errors_ = errors;
    where_ = where;
    for (size_t i = 0; i < errors.size(); ++i)
        for (std::uint32_t p : where[i]) add(p, errors[i] * errors[i]);
    std::vector<size_t> order(errors.size());
    std::iota(order.begin(), order.end(), size_t{0});
    auto weight = [&](size_t i) { return errors[i] * double(where[i].size()); };
    std::stable_sort(order.begin(), order.end(),
                     [&](size_t a, size_t b) { return weight(a) > weight(b); });
    std::vector<size_t> chosen;
    std::vector<bool> split(errors.size(), false);
    for (size_t i : order) {
        if (total_ <= target_ || where[i].empty()) break;
        chosen.push_back(i);
        split[i] = true;
        const double e2 = errors[i] * errors[i];
        for (std::uint32_t p : where[i]) add(p, (kSplitVariance - 1.0) * e2);
    }
    // Afresh, without the increments' rounding.
    total_ = 0;
    for (double v : variance_) total_ += per_pixel_ * std::sqrt(v);
    // Only the chosen cells stay pending (replaced by their children at the next level).
    for (size_t i = 0; i < errors_.size(); ++i)
        if (!split[i]) where_[i].clear();
    return chosen;
}

void PixelErrorBudget::refused(size_t cell) {
    const double e2 = errors_[cell] * errors_[cell];
    for (std::uint32_t p : where_[cell]) add(p, (1.0 - kSplitVariance) * e2);
    where_[cell].clear();
}

}  // namespace penumbra::techniques::adaptive
