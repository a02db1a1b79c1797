// `bitmask`'s light sample points and half-plane tables: see sample_pattern.h.
#include "renderer/techniques/bitmask/sample_pattern.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "renderer/core/error.h"
#include "renderer/techniques/jitter_hash.h"

namespace penumbra::techniques::bitmask {

Pattern patternFromName(std::string_view name) {
    if (name == "regular") return Pattern::Regular;
    if (name == "jittered") return Pattern::Jittered;
    if (name == "random") return Pattern::Random;
    std::string message = "technique.pattern: unknown pattern '";
    message += name;
    message += "' (regular, jittered, random)";
    throw InputError(message);
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

}  // namespace penumbra::techniques::bitmask
