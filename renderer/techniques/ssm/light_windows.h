// The light-centred views of `ssm`: the occluder map's window (axis-aligned with the rect light,
// texels of its aspect ratio) and the receiver/soft-shadow map's window on the virtual plane.
#pragma once

#include <glm/glm.hpp>

#include "renderer/passes/gpu_scene.h"
#include "renderer/scene/scene.h"

namespace penumbra::techniques::ssm {

// A perspective view from the light's centre along its forward axis: the window is the
// rectangle [lo, lo + size] at distance 1 in the light's (right, up) frame; depth is linear,
// (distance along forward - near) / (far - near).
struct LightWindow {
    glm::vec2 lo{0.0f}, size{0.0f};
    float near = 0.0f, far = 0.0f;
    bool empty() const { return !(size.x > 0.0f && size.y > 0.0f && far > near); }
    glm::mat4 viewProj(const scene::RectLight& light) const;
};

// The window that bounds BOUNDS seen from the light's centre (empty when nothing lies in front).
LightWindow windowOf(const scene::RectLight& light, const passes::Bounds& bounds);

// The occluder-map window: the casters' window grown along one axis so that its aspect ratio,
// and so that of every texel of a square map, is the light's.
LightWindow occluderWindow(const scene::RectLight& light, const passes::Bounds& casters);

// The soft-shadow-map window: the occluder window grown by the widest penumbra (section 3.3,
// half the light over the nearest occluder depth, less its value at the farthest receiver),
// clipped to the receivers' window, with the receivers' depth range.
LightWindow softShadowWindow(const scene::RectLight& light, const LightWindow& occluders,
                             const passes::Bounds& receivers);

}  // namespace penumbra::techniques::ssm
