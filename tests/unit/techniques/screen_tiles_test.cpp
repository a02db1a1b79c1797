// `adaptive`'s screen tiles without GL: each comparison pixel's tile at a stride, the tiles a
// split is refined in (its disagreeing pixels' tiles and their neighbours, within its own) and
// each tile's weights from the leaves live there.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <numeric>

#include "renderer/techniques/adaptive/screen_tiles.h"

namespace penumbra::techniques::adaptive {
namespace {

TEST(ScreenTiles, PixelsAtAStrideFallInTheTileOfTheirBlocksCentre) {
    const ScreenTiles tiles(32, 100, 70);  // 4 x 3 tiles, the last ones partial
    EXPECT_EQ(tiles.columns(), 4);
    EXPECT_EQ(tiles.count(), 12);
    const auto every = tiles.tilesAtStride(1);
    ASSERT_EQ(every.size(), 7000u);
    EXPECT_EQ(every[0], 0u);
    EXPECT_EQ(every[31], 0u);
    EXPECT_EQ(every[32], 1u);
    EXPECT_EQ(every[99], 3u);
    EXPECT_EQ(every[size_t(69 * 100 + 99)], 11u);
    // Stride 4: 25 x 18 pixels, each the centre (x * 4 + 2) of its block.
    const auto strided = tiles.tilesAtStride(4);
    ASSERT_EQ(strided.size(), 25u * 18u);
    EXPECT_EQ(strided[7], 0u);               // x 30
    EXPECT_EQ(strided[8], 1u);               // x 34
    EXPECT_EQ(strided[size_t(8 * 25)], 4u);  // y 34
    // Side 0: one tile, the whole view.
    const ScreenTiles one(0, 100, 70);
    EXPECT_EQ(one.count(), 1);
    const auto all = one.tilesAtStride(2);
    EXPECT_TRUE(std::all_of(all.begin(), all.end(), [](auto t) { return t == 0u; }));
}

TEST(ScreenTiles, ASplitIsRefinedAroundItsDisagreementsWithinItsOwnTiles) {
    const ScreenTiles tiles(10, 50, 50);  // 5 x 5
    const auto tile_of = tiles.tilesAtStride(1);
    const std::vector<std::uint32_t> pixels = {22 * 50 + 22};  // tile (2, 2)
    TileMask got = tiles.around(pixels, tile_of, tiles.all());
    EXPECT_EQ(std::accumulate(got.begin(), got.end(), 0), 9);
    for (int y = 1; y <= 3; ++y)
        for (int x = 1; x <= 3; ++x) EXPECT_EQ(got[size_t(y * 5 + x)], 1) << x << ", " << y;
    // At the corner of the view, the neighbours that exist.
    got = tiles.around(std::vector<std::uint32_t>{0}, tile_of, tiles.all());
    EXPECT_EQ(std::accumulate(got.begin(), got.end(), 0), 4);
    // Never outside the parent's tiles (its corners are tested nowhere else).
    TileMask parent(25, 0);
    parent[12] = parent[13] = 1;
    got = tiles.around(pixels, tile_of, parent);
    EXPECT_EQ(got, parent);
    got = tiles.around({}, tile_of, tiles.all());
    EXPECT_EQ(std::accumulate(got.begin(), got.end(), 0), 0);
}

TEST(ScreenTiles, EachTileWeighsTheLeavesLiveInIt) {
    using Weighting = LightQuadtree::Weighting;
    for (Weighting weighting : {Weighting::Area, Weighting::Paper, Weighting::Equal}) {
        LightQuadtree tree(3, false);
        const QuadtreeCell root = tree.root();
        // Tiles 0 and 1 of 3: the root split in tile 1 only; one child split further there.
        const auto children = tree.split(root);
        const auto grandchildren = tree.split(children[0]);
        std::vector<TiledLeaf> leaves = {{root, {1, 0, 1}}};
        for (size_t i = 1; i < children.size(); ++i) leaves.push_back({children[i], {0, 1, 0}});
        for (const auto& g : grandchildren) leaves.push_back({g, {0, 1, 0}});
        const TileWeights w = tileWeights(tree, weighting, leaves, 3);
        EXPECT_EQ(w.views, int(tree.samples().size()));
        EXPECT_EQ(w.set, (std::vector<std::uint32_t>{0, 1, 0}));  // tiles 0 and 2 alike
        ASSERT_EQ(w.weights.size(), 2u * (tree.samples().size() + 1));
        const size_t stride = tree.samples().size() + 1;
        // Set 0: the root's corners alone, a quarter each.
        for (size_t k = 0; k < tree.samples().size(); ++k)
            EXPECT_FLOAT_EQ(w.weights[k], k < 4 ? 0.25f : 0.0f) << k;
        EXPECT_FLOAT_EQ(w.weights[stride - 1], 1.0f);
        // Set 1: the whole refined tree, as its own weights.
        const std::vector<float> whole = tree.weights(weighting);
        for (size_t k = 0; k < whole.size(); ++k) EXPECT_EQ(w.weights[stride + k], whole[k]) << k;
        EXPECT_NEAR(w.weights[2 * stride - 1], 1.0f, 1e-6f);
        // The shader's blocks: set 0's four corners, set 1's every view.
        std::vector<std::uint32_t> tile_blocks;
        const auto blocks = w.blocks(tile_blocks);
        const std::uint32_t second = 2 + 2 * 4;
        EXPECT_EQ(tile_blocks, (std::vector<std::uint32_t>{0, second, 0}));
        ASSERT_EQ(blocks.size(), size_t(second) + 2 + 2 * whole.size());
        EXPECT_EQ(blocks[0], 4u);
        EXPECT_EQ(std::bit_cast<float>(blocks[1]), 1.0f);
        EXPECT_EQ(blocks[2], 0u);
        EXPECT_EQ(std::bit_cast<float>(blocks[3]), 0.25f);
        EXPECT_EQ(blocks[second], std::uint32_t(whole.size()));
        EXPECT_EQ(blocks[second + 2 + 2 * 5], 5u);
        EXPECT_EQ(std::bit_cast<float>(blocks[second + 3 + 2 * 5]), whole[5]);
    }
}

}  // namespace
}  // namespace penumbra::techniques::adaptive
