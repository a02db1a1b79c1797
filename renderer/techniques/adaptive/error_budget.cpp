// `adaptive`: the error-driven refinement rule: per-cell error estimates and the greedy choice of
// splits; see error_budget.h.
#include "renderer/techniques/adaptive/error_budget.h"

#include <algorithm>
#include <numeric>

namespace penumbra::techniques::adaptive {

double cellError(double light_share, double disagreeing, double shadowed) {
    if (shadowed <= 0 || disagreeing <= 0) return 0.0;
    return kDisagreementError * light_share * std::min(disagreeing / shadowed, 1.0);
}

std::vector<size_t> ErrorBudget::choose(const std::vector<double>& errors) {
    std::vector<size_t> order(errors.size());
    std::iota(order.begin(), order.end(), size_t{0});
    std::stable_sort(order.begin(), order.end(),
                     [&](size_t a, size_t b) { return errors[a] > errors[b]; });
    pending_ = 0;
    double total = settled_;
    for (double e : errors) total += e;
    std::vector<size_t> chosen;
    for (size_t i : order) {
        if (total > target_ && errors[i] > 0) {
            chosen.push_back(i);
            total -= 0.5 * errors[i];
            pending_ += 0.5 * errors[i];
        } else {
            settled_ += errors[i];
        }
    }
    return chosen;
}

void ErrorBudget::refused(double error) {
    pending_ -= 0.5 * error;
    settled_ += error;
}

}  // namespace penumbra::techniques::adaptive
