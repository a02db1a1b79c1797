// `bitmask`'s sample tables on the GPU: the half-plane tables of rectangles (a buffer), the
// edge tables of microquads (RGBA32UI, a 256-bit mask as two texels one row apart) and the points.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "renderer/gl/handles.h"

namespace penumbra::techniques::bitmask {

// A shader storage buffer of 2 (kTableResolution + 1) 256-bit masks as uvec4 pairs (words
// 0-3, 4-7): x >= u for the kTableResolution + 1 positions u, then y >= v (backproject.glsl;
// on llvmpipe a buffer load costs less than a texel fetch).
gl::Buffer halfPlaneBuffer(const std::vector<glm::vec2>& points);
// POINTS.size() x 1 RG32F: texel k holds sample k (backproject.glsl's horizon test).
gl::Texture pointTexture(const std::vector<glm::vec2>& points);
// kEdgeOffsets x 2 kEdgeAngles: rows 2a, 2a + 1 hold angle a (microquads.glsl).
gl::Texture edgeTexture(const std::vector<glm::vec2>& points);

}  // namespace penumbra::techniques::bitmask
