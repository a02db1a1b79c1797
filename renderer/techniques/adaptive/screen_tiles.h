// `adaptive`: square tiles of the camera view, and which of them each quadtree cell is refined
// in, so that a split's new maps are tested and weighted only where its parent's corners disagreed.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "renderer/techniques/adaptive/light_quadtree.h"

namespace penumbra::techniques::adaptive {

// Per tile, 1 where a cell (or a view) is live.
using TileMask = std::vector<std::uint8_t>;

class ScreenTiles {
public:
    // Tiles of SIDE pixels over a WIDTH x HEIGHT view; SIDE 0: one tile, the whole view.
    ScreenTiles(int side, int width, int height);

    int side() const { return side_; }
    int columns() const { return columns_; }
    int count() const { return columns_ * rows_; }
    TileMask all() const { return TileMask(size_t(count()), 1); }
    // The tile of each pixel of a comparison view read at STRIDE (the centre pixel of each
    // STRIDE x STRIDE block, as LitBits::read samples them), in its pixels' order.
    std::vector<std::uint32_t> tilesAtStride(int stride) const;
    // The tiles of PIXELS (TILE_OF's indices) and their 8 neighbours, within WITHIN: where a
    // split's children are refined (the neighbours for a penumbra its parent's corners
    // straddle just outside the pixels where they disagree).
    TileMask around(std::span<const std::uint32_t> pixels, std::span<const std::uint32_t> tile_of,
                    const TileMask& within) const;

private:
    int side_, width_, height_, columns_, rows_;
};

// A cell with the tiles where it is a leaf: live, and not split there.
struct TiledLeaf {
    QuadtreeCell cell;
    TileMask tiles;
};

// Each tile's sample weights: the weights of the leaves live in it (LightQuadtree::weights
// over them), shared between tiles that have the same leaves.
struct TileWeights {
    int views = 0;                   // weights per set
    std::vector<std::uint32_t> set;  // per tile: its set
    std::vector<float> weights;      // set-major: views weights, then their sum in float

    // lit_eval.frag's layout: per set a block [n, its sum's bits, then view k and w_k's bits
    // for the n views of nonzero weight, ascending], and per tile its set's block's offset
    // (into TILE_BLOCKS).
    std::vector<std::uint32_t> blocks(std::vector<std::uint32_t>& tile_blocks) const;
};
TileWeights tileWeights(const LightQuadtree& tree, LightQuadtree::Weighting weighting,
                        std::span<const TiledLeaf> leaves, int tiles);

}  // namespace penumbra::techniques::adaptive
