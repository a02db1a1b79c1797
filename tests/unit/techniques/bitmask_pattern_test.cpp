// `bitmask`'s light sample patterns and half-plane tables: the patterns are stratified as
// promised, and a rectangle's mask from four table lookups equals the samples inside it.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <utility>

#include "renderer/core/error.h"
#include "renderer/techniques/bitmask/sample_pattern.h"
#include "renderer/techniques/jitter_hash.h"

using namespace penumbra::techniques::bitmask;

namespace {
int popcount(const Mask& m) {
    int n = 0;
    for (auto w : m) n += std::popcount(w);
    return n;
}
}  // namespace

TEST(BitmaskPattern, GridsAndBadBitCounts) {
    EXPECT_EQ(sampleGrid(64), glm::ivec2(8, 8));
    EXPECT_EQ(sampleGrid(128), glm::ivec2(16, 8));
    EXPECT_EQ(sampleGrid(256), glm::ivec2(16, 16));
    EXPECT_THROW(sampleGrid(100), penumbra::InputError);
    EXPECT_THROW(patternFromName("poisson"), penumbra::InputError);
}

TEST(BitmaskPattern, JitteredAndRegularAreStratified) {
    for (Pattern pattern : {Pattern::Regular, Pattern::Jittered}) {
        const auto points = samplePoints(256, pattern, 7);
        ASSERT_EQ(points.size(), 256u);
        for (int k = 0; k < 256; ++k) {
            // Sample k lies in its own 1/16 cell of the 16 x 16 grid.
            EXPECT_EQ(int(std::floor(points[size_t(k)].x * 16)), k % 16);
            EXPECT_EQ(int(std::floor(points[size_t(k)].y * 16)), k / 16);
        }
    }
    const auto regular = samplePoints(64, Pattern::Regular, 1);
    EXPECT_NEAR(regular[0].x, 1.0 / 16.0, 1.0 / kTableResolution);  // the cell centre
}

TEST(BitmaskPattern, RandomIsNotStratifiedButInside) {
    const auto points = samplePoints(256, Pattern::Random, 3);
    int outside_cell = 0;
    for (int k = 0; k < 256; ++k) {
        const auto& p = points[size_t(k)];
        EXPECT_TRUE(p.x > 0 && p.x < 1 && p.y > 0 && p.y < 1);
        outside_cell += int(std::floor(p.x * 16)) != k % 16;
    }
    EXPECT_GT(outside_cell, 128);  // a random point lands in its own column 1 time in 16
}

TEST(BitmaskPattern, TableMasksEqualBruteForceRectangles) {
    for (int bits : {64, 128, 256}) {
        const auto points = samplePoints(bits, Pattern::Jittered, 1);
        const auto tables = halfPlaneTables(points);
        EXPECT_EQ(popcount(rectMask(tables, {0, 0}, {1, 1})), bits);
        EXPECT_EQ(popcount(rectMask(tables, {0.5f, 0.2f}, {0.5f, 0.9f})), 0);
        for (std::uint32_t trial = 0; trial < 500; ++trial) {
            glm::vec2 a(penumbra::techniques::hashToUnit(9, trial, 0),
                        penumbra::techniques::hashToUnit(9, trial, 1));
            glm::vec2 b(penumbra::techniques::hashToUnit(9, trial, 2),
                        penumbra::techniques::hashToUnit(9, trial, 3));
            const glm::vec2 lo = glm::min(a, b), hi = glm::max(a, b);
            const Mask m = rectMask(tables, lo, hi);
            for (int k = 0; k < bits; ++k) {
                const auto& p = points[size_t(k)];
                const bool inside = p.x >= lo.x && p.x < hi.x && p.y >= lo.y && p.y < hi.y;
                const bool set = (m[size_t(k / 32)] >> (k % 32)) & 1u;
                ASSERT_EQ(set, inside) << "bits " << bits << " trial " << trial << " sample " << k;
            }
            for (int w = (bits + 31) / 32; w < kMaskWords; ++w) EXPECT_EQ(m[size_t(w)], 0u);
        }
    }
}

TEST(BitmaskPattern, EdgeTableTrianglesMatchBruteForceAwayFromEdges) {
    const auto points = samplePoints(256, Pattern::Jittered, 1);
    const auto table = edgeTable(points);
    ASSERT_EQ(table.size(), size_t(kEdgeAngles) * kEdgeOffsets);
    auto entry = [&](glm::vec2 a, glm::vec2 b) {
        const glm::ivec2 i = edgeIndex(a, b);
        return table[size_t(i.x) * kEdgeOffsets + size_t(i.y)];
    };
    // Edge bins quantise the line by at most half an angle bin (pi / 256 at up to the light's
    // half diagonal, 0.0061) plus half an offset bin (0.0028): samples farther than 0.01 from
    // an edge must be classified exactly.
    const float tolerance = 0.01f;
    long checked = 0;
    for (std::uint32_t trial = 0; trial < 300; ++trial) {
        glm::vec2 v[3];
        for (int k = 0; k < 3; ++k)
            v[k] = {
                penumbra::techniques::hashToUnit(5, trial, std::uint32_t(2 * k)) * 1.4f - 0.2f,
                penumbra::techniques::hashToUnit(5, trial, std::uint32_t(2 * k + 1)) * 1.4f - 0.2f};
        const float area =
            (v[1].x - v[0].x) * (v[2].y - v[0].y) - (v[1].y - v[0].y) * (v[2].x - v[0].x);
        if (std::fabs(area) < 0.01f) continue;
        if (area < 0) std::swap(v[1], v[2]);  // counter-clockwise: inside is left of each edge
        Mask m{};
        const Mask e0 = entry(v[0], v[1]), e1 = entry(v[1], v[2]), e2 = entry(v[2], v[0]);
        for (int w = 0; w < kMaskWords; ++w)
            m[size_t(w)] = e0[size_t(w)] & e1[size_t(w)] & e2[size_t(w)];
        for (size_t k = 0; k < points.size(); ++k) {
            float nearest = 1e9f;
            bool inside = true;
            for (int i = 0; i < 3; ++i) {
                const glm::vec2 a = v[i], b = v[(i + 1) % 3];
                const glm::vec2 n = glm::normalize(glm::vec2(-(b - a).y, (b - a).x));
                const float d = glm::dot(n, points[k] - a);
                inside = inside && d >= 0;
                nearest = std::min(nearest, std::fabs(d));
            }
            if (nearest < tolerance) continue;
            ++checked;
            ASSERT_EQ(bool((m[k / 32] >> (k % 32)) & 1u), inside) << "trial " << trial;
        }
    }
    EXPECT_GT(checked, 30000);
}
