// Light-centred views: the window from a rect light's centre that bounds a box, and the
// occluder-map window (axis-aligned with the light, texels of its aspect ratio) that the light
// depth maps of `ssm`, `bitmask` and `css` are rendered through.
#pragma once

#include <glm/glm.hpp>

#include <vector>

#include "renderer/passes/gpu_scene.h"
#include "renderer/scene/scene.h"

namespace penumbra::passes {

// A perspective view from the light's centre along its forward axis: the window is the
// rectangle [lo, lo + size] at distance 1 in the light's (right, up) frame; depth is linear,
// (distance along forward - near) / (far - near).
struct LightWindow {
    glm::vec2 lo{0.0f}, size{0.0f};
    float near = 0.0f, far = 0.0f;
    bool empty() const { return !(size.x > 0.0f && size.y > 0.0f && far > near); }
    glm::mat4 viewProj(const scene::RectLight& light) const;
};

// The corners, relative to ORIGIN, of the boxes that reach in front of the plane through ORIGIN
// normal to FORWARD: a box wholly behind the light's plane lies on no ray the light sends.
std::vector<glm::vec3> cornersInFront(Boxes boxes, const glm::vec3& origin,
                                      const glm::vec3& forward);

// The window that bounds BOXES seen from the light's centre (empty when none lies in front).
LightWindow windowOf(const scene::RectLight& light, Boxes boxes);

// The occluder-map window: the casters' window grown along one axis so that its aspect ratio,
// and so that of every texel of a square map, is the light's.
LightWindow occluderWindow(const scene::RectLight& light, Boxes casters);

}  // namespace penumbra::passes
