// `adaptive`: counts over the per-pixel shadow bits of a level's maps; see shadow_bits.h.
#include "renderer/techniques/adaptive/shadow_bits.h"

namespace penumbra::techniques::adaptive {

double ShadowBits::anyShadowed(std::span<const int> slots) const {
    size_t n = 0;
    for (size_t p = 0; p < pixels; ++p) {
        bool any = false;
        for (int s : slots) any = any || shadowed(p, s);
        n += any;
    }
    return double(n) * scale;
}

std::vector<std::uint32_t> ShadowBits::disagreeing(
    std::span<const std::pair<int, int>> pairs) const {
    std::vector<std::uint32_t> out;
    for (size_t p = 0; p < pixels; ++p)
        for (auto [a, b] : pairs)
            if (shadowed(p, a) != shadowed(p, b)) {
                out.push_back(std::uint32_t(p));
                break;
            }
    return out;
}

}  // namespace penumbra::techniques::adaptive
