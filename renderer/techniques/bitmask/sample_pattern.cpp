// `bitmask`'s light sample points and half-plane tables: see sample_pattern.h.
#include "renderer/techniques/bitmask/sample_pattern.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "renderer/core/error.h"
#include "renderer/techniques/jitter_hash.h"

namespace penumbra::techniques::bitmask {

Pattern patternFromName(std::string_view name) {
    std::string known;
    for (std::size_t i = 0; i < kPattern.names.size(); ++i) {
        if (kPattern.names[i] == name) return static_cast<Pattern>(i);
        known += (i ? ", " : "") + std::string(kPattern.names[i]);
    }
    throw InputError("technique.pattern: unknown pattern '" + std::string(name) + "' (" + known +
                     ")");
}

glm::ivec2 sampleGrid(int bits) {
    if (bits == 64) return {8, 8};
    if (bits == 128) return {16, 8};
    if (bits == 256) return {16, 16};
    throw InputError("technique.bits: must be 64, 128 or 256");
}

namespace {
// The centre of the table cell holding U, so that a table edge never splits a sample.
float snap(float u) {
    const float r = static_cast<float>(kTableResolution);
    const float cell = std::clamp(std::floor(u * r), 0.0f, r - 1.0f);
    return (cell + 0.5f) / r;
}
}  // namespace

std::vector<glm::vec2> samplePoints(int bits, Pattern pattern, std::uint32_t seed) {
    const glm::ivec2 grid = sampleGrid(bits);
    std::vector<glm::vec2> points;
    points.reserve(static_cast<size_t>(bits));
    for (int j = 0; j < grid.y; ++j)
        for (int i = 0; i < grid.x; ++i) {
            const auto k = static_cast<std::uint32_t>(j * grid.x + i);
            glm::vec2 p;
            if (pattern == Pattern::Random) {
                p = {hashToUnit(seed, k, 0), hashToUnit(seed, k, 1)};
            } else {
                glm::vec2 offset(0.5f);
                if (pattern == Pattern::Jittered)
                    offset = {hashToUnit(seed, k, 2), hashToUnit(seed, k, 3)};
                p = (glm::vec2(float(i), float(j)) + offset) / glm::vec2(grid);
            }
            points.push_back({snap(p.x), snap(p.y)});
        }
    return points;
}

HalfPlaneTables halfPlaneTables(const std::vector<glm::vec2>& points) {
    HalfPlaneTables t;
    t.x.assign(kTableResolution + 1, Mask{});
    t.y.assign(kTableResolution + 1, Mask{});
    for (int i = 0; i <= kTableResolution; ++i) {
        const float edge = static_cast<float>(i) / kTableResolution;
        for (size_t k = 0; k < points.size(); ++k) {
            const std::uint32_t bit = 1u << (k % 32);
            if (points[k].x >= edge) t.x[size_t(i)][k / 32] |= bit;
            if (points[k].y >= edge) t.y[size_t(i)][k / 32] |= bit;
        }
    }
    return t;
}

int maskIndex(float u) {
    const float i = std::ceil(u * kTableResolution - 0.5f);
    return static_cast<int>(std::clamp(i, 0.0f, static_cast<float>(kTableResolution)));
}

Mask rectMask(const HalfPlaneTables& t, glm::vec2 lo, glm::vec2 hi) {
    const Mask &x0 = t.x[size_t(maskIndex(lo.x))], &x1 = t.x[size_t(maskIndex(hi.x))];
    const Mask &y0 = t.y[size_t(maskIndex(lo.y))], &y1 = t.y[size_t(maskIndex(hi.y))];
    Mask m{};
    for (int w = 0; w < kMaskWords; ++w) m[w] = x0[w] & ~x1[w] & y0[w] & ~y1[w];
    return m;
}

namespace {
constexpr float kTwoPi = 6.28318530718f;
constexpr float kHalfDiagonal = 0.70710678f;
}  // namespace

std::vector<Mask> edgeTable(const std::vector<glm::vec2>& points) {
    std::vector<Mask> table(size_t(kEdgeAngles) * kEdgeOffsets, Mask{});
    for (int a = 0; a < kEdgeAngles; ++a) {
        const float angle = kTwoPi * static_cast<float>(a) / kEdgeAngles;
        const glm::vec2 n(std::cos(angle), std::sin(angle));
        for (int o = 0; o < kEdgeOffsets; ++o) {
            const float d = -kHalfDiagonal + 2.0f * kHalfDiagonal * static_cast<float>(o) /
                                                 static_cast<float>(kEdgeOffsets - 1);
            Mask& m = table[size_t(a) * kEdgeOffsets + size_t(o)];
            for (size_t k = 0; k < points.size(); ++k)
                if (glm::dot(n, points[k] - glm::vec2(0.5f)) >= d) m[k / 32] |= 1u << (k % 32);
        }
    }
    return table;
}

glm::ivec2 edgeIndex(glm::vec2 a, glm::vec2 b) {
    const glm::vec2 e = b - a;
    const glm::vec2 n = glm::normalize(glm::vec2(-e.y, e.x));  // left of A -> B
    float angle = std::atan2(n.y, n.x);
    if (angle < 0.0f) angle += kTwoPi;
    const int ai = static_cast<int>(std::round(angle / kTwoPi * kEdgeAngles)) % kEdgeAngles;
    const float d = glm::dot(n, a - glm::vec2(0.5f));
    const float o = (d + kHalfDiagonal) / (2.0f * kHalfDiagonal) * (kEdgeOffsets - 1);
    return {ai, static_cast<int>(std::clamp(std::round(o), 0.0f, float(kEdgeOffsets - 1)))};
}

}  // namespace penumbra::techniques::bitmask
