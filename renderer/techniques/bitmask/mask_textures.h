// `bitmask`'s sample tables on the GPU (RGBA32UI, a 256-bit mask as two texels one row
// apart): the half-plane tables of rectangles and the edge tables of microquads; and the
// sample points themselves.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "renderer/gl/handles.h"

namespace penumbra::techniques::bitmask {

// (kTableResolution + 1) x 4: rows 0-1 x >= u, rows 2-3 y >= v (backproject.glsl).
gl::Texture halfPlaneTexture(const std::vector<glm::vec2>& points);
// POINTS.size() x 1 RG32F: texel k holds sample k (backproject.glsl's horizon test).
gl::Texture pointTexture(const std::vector<glm::vec2>& points);
// kEdgeOffsets x 2 kEdgeAngles: rows 2a, 2a + 1 hold angle a (microquads.glsl).
gl::Texture edgeTexture(const std::vector<glm::vec2>& points);

}  // namespace penumbra::techniques::bitmask
