// `adaptive`: counts over the per-pixel shadow bits of a level's maps; see shadow_bits.h.
#include "renderer/techniques/adaptive/shadow_bits.h"

#include <algorithm>

namespace penumbra::techniques::adaptive {

void ShadowBits::index() {
    active.clear();
    for (size_t p = 0; p < pixels; ++p) {
        const std::uint32_t* w = &bits[p * size_t(words)];
        if (std::any_of(w, w + words, [](std::uint32_t v) { return v != 0; }))
            active.push_back(std::uint32_t(p));
    }
}

double ShadowBits::anyShadowed(std::span<const int> slots) const {
    size_t n = 0;
    for (size_t p : active) {
        bool any = false;
        for (int s : slots) any = any || shadowed(p, s);
        n += any;
    }
    return double(n) * scale;
}

std::vector<std::uint32_t> ShadowBits::disagreeing(
    std::span<const std::pair<int, int>> pairs) const {
    std::vector<std::uint32_t> out;
    for (size_t p : active)
        for (auto [a, b] : pairs)
            if (shadowed(p, a) != shadowed(p, b)) {
                out.push_back(std::uint32_t(p));
                break;
            }
    return out;
}

}  // namespace penumbra::techniques::adaptive
