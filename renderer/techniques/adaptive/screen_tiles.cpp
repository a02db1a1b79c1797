// `adaptive`: the camera view's tiles a cell is refined in, and each tile's sample weights; see
// screen_tiles.h.
#include "renderer/techniques/adaptive/screen_tiles.h"

#include <algorithm>
#include <bit>
#include <map>

namespace penumbra::techniques::adaptive {

ScreenTiles::ScreenTiles(int side, int width, int height)
    : side_(side > 0 ? side : std::max({width, height, 1})),
      width_(width),
      height_(height),
      columns_(std::max(1, (width + side_ - 1) / side_)),
      rows_(std::max(1, (height + side_ - 1) / side_)) {}

std::vector<std::uint32_t> ScreenTiles::tilesAtStride(int stride) const {
    stride = std::max(stride, 1);
    const int w = (width_ + stride - 1) / stride, h = (height_ + stride - 1) / stride;
    std::vector<std::uint32_t> out;
    out.reserve(size_t(w) * size_t(h));
    for (int y = 0; y < h; ++y) {
        const int row = std::min(y * stride + stride / 2, height_ - 1) / side_;
        for (int x = 0; x < w; ++x)
            out.push_back(std::uint32_t(row * columns_ +
                                        std::min(x * stride + stride / 2, width_ - 1) / side_));
    }
    return out;
}

TileMask ScreenTiles::around(std::span<const std::uint32_t> pixels,
                             std::span<const std::uint32_t> tile_of, const TileMask& within) const {
    TileMask hit(size_t(count()), 0), out(size_t(count()), 0);
    for (std::uint32_t p : pixels) hit[tile_of[p]] = 1;
    for (int ty = 0; ty < rows_; ++ty)
        for (int tx = 0; tx < columns_; ++tx) {
            if (!hit[size_t(ty * columns_ + tx)]) continue;
            for (int y = std::max(ty - 1, 0); y <= std::min(ty + 1, rows_ - 1); ++y)
                for (int x = std::max(tx - 1, 0); x <= std::min(tx + 1, columns_ - 1); ++x)
                    out[size_t(y * columns_ + x)] = 1;
        }
    for (size_t t = 0; t < out.size(); ++t) out[t] &= within[t];
    return out;
}

TileWeights tileWeights(const LightQuadtree& tree, LightQuadtree::Weighting weighting,
                        std::span<const TiledLeaf> leaves, int tiles) {
    TileWeights out;
    out.views = int(tree.samples().size());
    out.set.resize(size_t(tiles));
    std::map<std::vector<std::uint32_t>, std::uint32_t> sets;  // a tile's leaves -> its set
    std::vector<QuadtreeCell> cells;
    for (int t = 0; t < tiles; ++t) {
        std::vector<std::uint32_t> key;
        for (size_t i = 0; i < leaves.size(); ++i)
            if (leaves[i].tiles[size_t(t)]) key.push_back(std::uint32_t(i));
        const auto [it, added] = sets.try_emplace(key, std::uint32_t(sets.size()));
        out.set[size_t(t)] = it->second;
        if (!added) continue;
        cells.clear();
        for (std::uint32_t i : key) cells.push_back(leaves[i].cell);
        const std::vector<float> w = tree.weights(weighting, cells);
        float sum = 0.0f;  // in the order and precision lit_eval.frag adds them
        for (float x : w) sum += x;
        out.weights.insert(out.weights.end(), w.begin(), w.end());
        out.weights.push_back(sum);
    }
    return out;
}

std::vector<std::uint32_t> TileWeights::blocks(std::vector<std::uint32_t>& tile_blocks) const {
    const size_t stride = size_t(views) + 1;
    std::vector<std::uint32_t> out, offset;
    for (size_t s = 0; s < weights.size() / stride; ++s) {
        offset.push_back(std::uint32_t(out.size()));
        const float* w = &weights[s * stride];
        out.push_back(0);
        out.push_back(std::bit_cast<std::uint32_t>(w[views]));
        for (size_t k = 0; k < size_t(views); ++k)
            if (w[k] != 0.0f) {
                ++out[offset.back()];
                out.push_back(std::uint32_t(k));
                out.push_back(std::bit_cast<std::uint32_t>(w[k]));
            }
    }
    tile_blocks.clear();
    for (std::uint32_t s : set) tile_blocks.push_back(offset[s]);
    return out;
}

}  // namespace penumbra::techniques::adaptive
