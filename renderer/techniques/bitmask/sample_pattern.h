// `bitmask`'s light sample points (regular, jittered or random, 64 to 256 of them) and the
// half-plane tables that turn a back-projected rectangle into an occlusion bitmask with four
// lookups (Schwarz & Stamminger, Bitmask Soft Shadows): bits of samples with x >= u (or y >= v).
#pragma once

#include <array>
#include <cstdint>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

#include "renderer/core/params.h"

namespace penumbra::techniques::bitmask {

constexpr int kMaskWords = 8;           // 256 bits, the widest bitmask
constexpr int kTableResolution = 1024;  // positions per light axis of the half-plane tables

enum class Pattern { Regular, Jittered, Random };
inline constexpr EnumKey<Pattern, 3> kPattern{"pattern", {"regular", "jittered", "random"}};
Pattern patternFromName(std::string_view name);  // one of kPattern's names

// The sample grid of BITS samples: 64 = 8 x 8, 128 = 16 x 8, 256 = 16 x 16.
glm::ivec2 sampleGrid(int bits);

// BITS sample points in [0,1)^2, bit k = sample k. Coordinates are snapped to the centres of
// kTableResolution cells so that the half-plane tables classify them exactly.
std::vector<glm::vec2> samplePoints(int bits, Pattern pattern, std::uint32_t seed);

using Mask = std::array<std::uint32_t, kMaskWords>;

// The half-plane masks: entry i of X holds the samples with x >= i / kTableResolution
// (i = 0 .. kTableResolution, so kTableResolution + 1 entries); the same for Y.
struct HalfPlaneTables {
    std::vector<Mask> x, y;
};
HalfPlaneTables halfPlaneTables(const std::vector<glm::vec2>& points);

// The table index of a rectangle edge at U: the samples at or right of U are those of
// entry ceil(U * R - 1/2) (mirrored by maskIndex() in glsl/techniques/bitmask/backproject.glsl).
int maskIndex(float u);

// The samples inside [U0, U1) x [V0, V1), from the tables (what the shader computes).
Mask rectMask(const HalfPlaneTables& t, glm::vec2 lo, glm::vec2 hi);

// The edge tables of microquads (Bitmask Soft Shadows): entry (a, o) holds the samples s with
// dot(n, s - (0.5, 0.5)) >= d for the normal n at angle 2 pi a / kEdgeAngles and the offset
// d = -r + 2 r o / (kEdgeOffsets - 1), r = sqrt(2) / 2 (the light's half diagonal); row-major
// by angle. A back-projected triangle's mask is the AND of its three edges' entries.
constexpr int kEdgeAngles = 256;
constexpr int kEdgeOffsets = 256;
std::vector<Mask> edgeTable(const std::vector<glm::vec2>& points);

// The entry of the half-plane left of the directed edge A -> B (mirrored by edgeMask() in
// glsl/techniques/bitmask/backproject.glsl): its angle and offset bins.
glm::ivec2 edgeIndex(glm::vec2 a, glm::vec2 b);

}  // namespace penumbra::techniques::bitmask
