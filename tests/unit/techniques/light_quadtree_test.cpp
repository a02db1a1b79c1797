// `adaptive`'s light subdivision without GL: corner samples, shared samples between
// neighbouring cells, the compared pairs, jitter bounds and the three weightings.
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <set>

#include "renderer/techniques/adaptive/light_quadtree.h"

namespace penumbra::techniques::adaptive {
namespace {

using W = LightQuadtree::Weighting;

float sum(const std::vector<float>& v) {
    return std::accumulate(v.begin(), v.end(), 0.0f);
}

TEST(LightQuadtree, StartsAtTheCornersAndComparesTheDiagonals) {
    LightQuadtree t(3, false);
    ASSERT_EQ(t.samples().size(), 4u);
    std::set<std::pair<float, float>> uv;
    for (const auto& s : t.samples()) uv.insert({s.uv.x, s.uv.y});
    EXPECT_EQ(uv, (std::set<std::pair<float, float>>{{0, 0}, {1, 0}, {1, 1}, {0, 1}}));
    const auto pairs = t.comparisons(t.root());
    ASSERT_EQ(pairs.size(), 2u);
    for (auto [a, b] : pairs) {
        // Diagonally opposed: the two corners differ in both coordinates.
        EXPECT_NE(t.samples()[size_t(a)].uv.x, t.samples()[size_t(b)].uv.x);
        EXPECT_NE(t.samples()[size_t(a)].uv.y, t.samples()[size_t(b)].uv.y);
    }
}

TEST(LightQuadtree, NeighboursShareTheirEdgeSamples) {
    LightQuadtree t(3, false);
    EXPECT_EQ(t.newSamples(t.root()), 5);  // 4 edge midpoints and the centre
    const auto children = t.split(t.root());
    ASSERT_EQ(children.size(), 4u);
    EXPECT_EQ(t.samples().size(), 9u);
    EXPECT_EQ(t.leaves().size(), 4u);
    for (const auto& s : t.samples()) EXPECT_LE(s.depth, 1);
    // The first child's 5 split points are all new; its neighbour then shares one edge midpoint.
    EXPECT_EQ(t.newSamples(children[0]), 5);
    t.split(children[0]);
    EXPECT_EQ(t.newSamples(children[1]), 4);
    t.split(children[1]);
    EXPECT_EQ(t.samples().size(), 18u);
    EXPECT_EQ(t.leaves().size(), 10u);
}

TEST(LightQuadtree, FullRefinementIsTheRegularGrid) {
    LightQuadtree t(2, false);
    std::vector<QuadtreeCell> cells{t.root()};
    for (int d = 0; d < 2; ++d) {
        std::vector<QuadtreeCell> next;
        for (const auto& c : cells)
            for (const auto& child : t.split(c)) next.push_back(child);
        cells = next;
    }
    EXPECT_EQ(t.samples().size(), 25u);  // (2^2 + 1)^2, each rendered once
    // Area weights on the full grid are the 2D trapezoid rule: corner 1/64, edge 2/64, inner 4/64.
    const auto w = t.weights(W::Area);
    for (size_t i = 0; i < w.size(); ++i) {
        const auto g = t.samples()[i].grid;
        const int edges = (g.x == 0 || g.x == 4) + (g.y == 0 || g.y == 4);
        EXPECT_NEAR(w[i], (edges == 2 ? 1.0f : edges == 1 ? 2.0f : 4.0f) / 64.0f, 1e-6f);
    }
}

TEST(LightQuadtree, WeightingsAreNormalised) {
    LightQuadtree t(3, false);
    const auto c = t.split(t.root());
    t.split(c[2]);
    for (W w : {W::Area, W::Paper, W::Equal}) EXPECT_NEAR(sum(t.weights(w)), 1.0f, 1e-6f);
    // Paper (eq. 5): depth d weighs 1/(2^d + 1)^2 before normalisation.
    const auto paper = t.weights(W::Paper);
    float d0 = 0, d2 = 0;
    for (size_t i = 0; i < paper.size(); ++i) {
        if (t.samples()[i].depth == 0) d0 = paper[i];
        if (t.samples()[i].depth == 2) d2 = paper[i];
    }
    EXPECT_NEAR(d0 / d2, 25.0f / 4.0f, 1e-4f);
    // Area: the split quadrant's corners carry its quarter of the light among more samples.
    const auto area = t.weights(W::Area);
    EXPECT_NEAR(area[0], 1.0f / 16.0f, 1e-6f);  // corner (0,0) of the unsplit quadrant 0
}

TEST(LightQuadtree, LinearLightsSplitIntoSegments) {
    LightQuadtree t(3, true);
    ASSERT_EQ(t.samples().size(), 2u);
    EXPECT_EQ(t.comparisons(t.root()).size(), 1u);  // its two ends
    EXPECT_EQ(t.newSamples(t.root()), 1);
    const auto halves = t.split(t.root());
    ASSERT_EQ(halves.size(), 2u);
    for (const auto& s : t.samples()) EXPECT_FLOAT_EQ(s.uv.y, 0.5f);  // the centre line
    // Eq. 6: ends 1/2 each, the midpoint 1/3, normalised.
    const auto w = t.weights(W::Paper);
    EXPECT_NEAR(w[2] / w[0], (1.0f / 3.0f) / 0.5f, 1e-5f);
    EXPECT_NEAR(sum(t.weights(W::Area)), 1.0f, 1e-6f);
}

TEST(LightQuadtree, JitterStaysInTheSampleCellAndIsSeeded) {
    LightQuadtree a(3, false, true, 7), b(3, false, true, 7), c(3, false, true, 8);
    for (auto* t : {&a, &b, &c}) {
        auto kids = t->split(t->root());
        t->split(kids[1]);
    }
    const float half = 0.5f / 8.0f;  // half a finest-grid cell
    bool differs = false;
    for (size_t i = 0; i < a.samples().size(); ++i) {
        const auto& s = a.samples()[i];
        const glm::vec2 grid = glm::vec2(s.grid) / 8.0f;
        EXPECT_LE(std::fabs(s.uv.x - grid.x), half + 1e-6f);
        EXPECT_LE(std::fabs(s.uv.y - grid.y), half + 1e-6f);
        EXPECT_GE(s.uv.x, 0.0f);
        EXPECT_LE(s.uv.y, 1.0f);
        EXPECT_EQ(s.uv, b.samples()[i].uv);  // same seed, same pattern
        differs |= s.uv != c.samples()[i].uv;
    }
    EXPECT_TRUE(differs);
}

// A sample on the light's edge stands for the half cell inside the light: its jitter is uniform
// there, never piled on the edge (clamping a point of the whole cell put half of them on it).
TEST(LightQuadtree, EdgeSamplesJitterUniformlyInsideTheLight) {
    const float half = 0.5f / 8.0f;
    int on_edge = 0;
    double sum_x = 0, sum_y = 0;
    const int seeds = 400;
    for (int seed = 1; seed <= seeds; ++seed) {
        const LightQuadtree t(3, false, true, unsigned(seed));
        const glm::vec2 uv = t.samples()[0].uv;  // the corner (0, 0)
        EXPECT_GE(std::min(uv.x, uv.y), 0.0f);
        EXPECT_LE(std::max(uv.x, uv.y), half);
        on_edge += uv.x == 0.0f || uv.y == 0.0f;
        sum_x += uv.x;
        sum_y += uv.y;
    }
    EXPECT_LE(on_edge, 2);  // the old clamp: about 3/4 of them
    // Uniform in [0, half]: mean half / 2 (the clamp's was half / 4), its error about 0.0009.
    EXPECT_NEAR(sum_x / seeds, 0.5 * half, 0.004);
    EXPECT_NEAR(sum_y / seeds, 0.5 * half, 0.004);
}

}  // namespace
}  // namespace penumbra::techniques::adaptive
