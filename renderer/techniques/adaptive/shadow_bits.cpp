// `adaptive`: counts over the per-pixel shadow bits of a level's maps; see shadow_bits.h.
#include "renderer/techniques/adaptive/shadow_bits.h"

#include <algorithm>
#include <utility>

#include "renderer/core/parallel_chunks.h"

namespace penumbra::techniques::adaptive {

namespace {

// Chunks of the pixels or active pixels a thread takes at least (parallel_chunks.h).
constexpr size_t kGrain = 16384;

}  // namespace

void ShadowBits::index() {
    std::vector<std::vector<std::uint32_t>> found(parallelThreads());
    const size_t chunks = parallelChunks(pixels, kGrain, [&](size_t c, size_t begin, size_t end) {
        for (size_t p = begin; p < end; ++p) {
            std::uint32_t any = 0;
            for (size_t k = 0; k < size_t(words); ++k) any |= bits[k * pixels + p];
            if (any) found[c].push_back(std::uint32_t(p));
        }
    });
    active.clear();
    for (size_t c = 0; c < chunks; ++c)
        active.insert(active.end(), found[c].begin(), found[c].end());
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
    const std::vector<std::pair<int, int>> group(pairs.begin(), pairs.end());
    return std::move(disagreements(std::span(&group, 1)).where[0]);
}

Disagreements ShadowBits::disagreements(std::span<const std::vector<std::pair<int, int>>> groups,
                                        bool where, std::span<const TileMask> masks,
                                        std::span<const std::uint32_t> tile_of) const {
    size_t pairs = 0;
    for (const auto& group : groups) pairs += group.size();
    // Contiguous chunks of the active pixels on threads of their own, each found as below; the
    // counts add up and the pixel lists join in chunk order (still ascending).
    std::vector<Disagreements> part(parallelThreads());
    const size_t chunks = parallelChunks(active.size(), kGrain, [&](size_t c, size_t b, size_t e) {
        part[c] = disagreementsIn(groups, pairs, where, masks, tile_of, b, e);
    });
    if (chunks == 1) return std::move(part[0]);
    Disagreements out;
    out.where.resize(groups.size());
    out.pairs.assign(pairs, 0);
    for (size_t c = 0; c < chunks; ++c) {
        for (size_t g = 0; g < groups.size(); ++g)
            out.where[g].insert(out.where[g].end(), part[c].where[g].begin(),
                                part[c].where[g].end());
        for (size_t q = 0; q < pairs; ++q) out.pairs[q] += part[c].pairs[q];
        out.anywhere.insert(out.anywhere.end(), part[c].anywhere.begin(), part[c].anywhere.end());
    }
    return out;
}

Disagreements ShadowBits::disagreementsIn(std::span<const std::vector<std::pair<int, int>>> groups,
                                          size_t pairs, bool where, std::span<const TileMask> masks,
                                          std::span<const std::uint32_t> tile_of, size_t begin,
                                          size_t end) const {
    // Blocks of active pixels, their words packed word-major: the loops over a block's pixels
    // below are plain array arithmetic the compiler vectorises, on data that stays in cache.
    constexpr size_t kBlock = 2048;
    Disagreements out;
    out.where.resize(groups.size());
    out.pairs.assign(pairs, 0);
    std::vector<std::uint32_t> packed(static_cast<size_t>(words) * kBlock);
    std::vector<std::uint8_t> any(kBlock), anywhere(kBlock), live(kBlock, 1);
    for (size_t first = begin; first < end; first += kBlock) {
        const size_t n = std::min(kBlock, end - first);
        for (size_t k = 0; k < size_t(words); ++k)
            for (size_t j = 0; j < n; ++j)
                packed[k * kBlock + j] = bits[k * pixels + active[first + j]];
        std::fill_n(anywhere.begin(), n, std::uint8_t{0});
        size_t q = 0;  // the pair's index in out.pairs
        for (size_t g = 0; g < groups.size(); ++g) {
            std::fill_n(any.begin(), n, std::uint8_t{0});
            if (!masks.empty())  // the group's tiles: elsewhere its corners' bits are not set
                for (size_t j = 0; j < n; ++j) live[j] = masks[g][tile_of[active[first + j]]];
            for (auto [a, b] : groups[g]) {
                const std::uint32_t* wa = &packed[size_t(a >> 5) * kBlock];
                const std::uint32_t* wb = &packed[size_t(b >> 5) * kBlock];
                const unsigned sa = unsigned(a & 31), sb = unsigned(b & 31);
                size_t count = 0;
                for (size_t j = 0; j < n; ++j) {
                    const std::uint32_t d = ((wa[j] >> sa) ^ (wb[j] >> sb)) & live[j];
                    count += d;
                    any[j] |= std::uint8_t(d);
                }
                out.pairs[q++] += count;
            }
            for (size_t j = 0; j < n; ++j)
                if (any[j]) {
                    if (where) out.where[g].push_back(active[first + j]);
                    anywhere[j] = 1;
                }
        }
        for (size_t j = 0; j < n; ++j)
            if (anywhere[j]) out.anywhere.push_back(active[first + j]);
    }
    return out;
}

}  // namespace penumbra::techniques::adaptive
