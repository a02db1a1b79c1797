// `adaptive`: which light-sample maps shadow each pixel of a comparison view, as one bit per map
// (read back from shadow_bits.frag), and the counts the refinement takes from them.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "renderer/techniques/adaptive/screen_tiles.h"

namespace penumbra::techniques::adaptive {

// What one pass over the shadowed pixels finds for groups of slot pairs (a cell's diagonals).
struct Disagreements {
    std::vector<std::vector<std::uint32_t>> where;  // per group: pixels where any pair disagrees
    std::vector<std::size_t> pairs;       // per pair, the groups' in order: its disagreeing pixels
    std::vector<std::uint32_t> anywhere;  // pixels where some pair of some group disagrees
};

struct ShadowBits {
    size_t pixels = 0;  // comparison-view pixels
    int words = 0;      // uint32 per pixel: bit i of word i / 32 is map slot i
    double scale = 1;   // G-buffer pixels each comparison pixel stands for (stride^2)
    // Word-major (word k of pixel p at k * pixels + p): LitBits' layout, read back as it is.
    std::vector<std::uint32_t> bits;
    // The pixels some slot shadows, ascending (index()); the counts below visit only these: a
    // pixel no map shadows (most of an image) can neither disagree nor count as shadowed.
    std::vector<std::uint32_t> active;

    // Fills ACTIVE from BITS; the producers call it once the bits are in.
    void index();
    bool shadowed(size_t pixel, int slot) const {
        return (bits[size_t(slot >> 5) * pixels + pixel] >> (slot & 31)) & 1u;
    }
    // Pixels (x scale) that any of SLOTS shadows.
    double anyShadowed(std::span<const int> slots) const;
    // The pixels (indices) where any of PAIRS of slots disagrees.
    std::vector<std::uint32_t> disagreeing(std::span<const std::pair<int, int>> pairs) const;
    // For each group of pairs of slots, the pixels where any of its pairs disagrees (left
    // empty without WHERE), and each pair's count, in one pass over the active pixels (the
    // refinement's per-level cost), the active pixels split between threads. With MASKS (one
    // per group), a group counts only the pixels of its tiles (TILE_OF: each pixel's tile).
    Disagreements disagreements(std::span<const std::vector<std::pair<int, int>>> groups,
                                bool where = true, std::span<const TileMask> masks = {},
                                std::span<const std::uint32_t> tile_of = {}) const;

private:
    // The same over active[BEGIN, END), for PAIRS pairs in all.
    Disagreements disagreementsIn(std::span<const std::vector<std::pair<int, int>>> groups,
                                  size_t pairs, bool where, std::span<const TileMask> masks,
                                  std::span<const std::uint32_t> tile_of, size_t begin,
                                  size_t end) const;
};

}  // namespace penumbra::techniques::adaptive
