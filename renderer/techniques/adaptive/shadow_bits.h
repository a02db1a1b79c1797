// `adaptive`: which light-sample maps shadow each pixel of a comparison view, as one bit per map
// (read back from shadow_bits.frag), and the counts the refinement takes from them.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

namespace penumbra::techniques::adaptive {

struct ShadowBits {
    size_t pixels = 0;                // comparison-view pixels
    int words = 0;                    // uint32 per pixel: bit i of word i / 32 is map slot i
    double scale = 1;                 // G-buffer pixels each comparison pixel stands for (stride^2)
    std::vector<std::uint32_t> bits;  // pixel-major
    // The pixels some slot shadows, ascending (index()); the counts below visit only these: a
    // pixel no map shadows (most of an image) can neither disagree nor count as shadowed.
    std::vector<std::uint32_t> active;

    // Fills ACTIVE from BITS; the producers call it once the bits are in.
    void index();
    bool shadowed(size_t pixel, int slot) const {
        return (bits[pixel * size_t(words) + size_t(slot >> 5)] >> (slot & 31)) & 1u;
    }
    // Pixels (x scale) that any of SLOTS shadows.
    double anyShadowed(std::span<const int> slots) const;
    // The pixels (indices) where any of PAIRS of slots disagrees.
    std::vector<std::uint32_t> disagreeing(std::span<const std::pair<int, int>> pairs) const;
};

}  // namespace penumbra::techniques::adaptive
