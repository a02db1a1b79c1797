// Nearest-name suggestions: see did_you_mean.h.
#include "renderer/core/did_you_mean.h"

#include <algorithm>

namespace penumbra {

std::size_t editDistance(std::string_view a, std::string_view b) {
    const std::size_t n = a.size(), m = b.size();
    // Three rows suffice for the swap of two neighbours (optimal string alignment).
    std::vector<std::size_t> two(m + 1), one(m + 1), row(m + 1);
    for (std::size_t j = 0; j <= m; ++j) one[j] = j;
    for (std::size_t i = 1; i <= n; ++i) {
        row[0] = i;
        for (std::size_t j = 1; j <= m; ++j) {
            const std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
            row[j] = std::min({one[j] + 1, row[j - 1] + 1, one[j - 1] + cost});
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
                row[j] = std::min(row[j], two[j - 2] + 1);
        }
        std::swap(two, one);
        std::swap(one, row);
    }
    return one[m];
}

std::string nearestName(std::string_view typed, std::span<const std::string_view> candidates) {
    const std::size_t limit = std::clamp<std::size_t>(typed.size() / 3, 1, 3);
    std::string best;
    std::size_t best_distance = limit + 1;
    for (std::string_view c : candidates) {
        const std::size_t d = editDistance(typed, c);
        if (d < best_distance && d > 0) {
            best_distance = d;
            best = std::string(c);
        }
    }
    return best;
}

std::string nearestName(std::string_view typed, const std::vector<std::string>& candidates) {
    std::vector<std::string_view> views(candidates.begin(), candidates.end());
    return nearestName(typed, std::span<const std::string_view>(views));
}

std::string didYouMean(std::string_view typed, std::span<const std::string_view> candidates) {
    const std::string near = nearestName(typed, candidates);
    return near.empty() ? std::string() : " (did you mean '" + near + "'?)";
}

std::string didYouMean(std::string_view typed, const std::vector<std::string>& candidates) {
    std::vector<std::string_view> views(candidates.begin(), candidates.end());
    return didYouMean(typed, std::span<const std::string_view>(views));
}

}  // namespace penumbra
