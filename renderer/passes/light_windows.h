// Light-centred views: the window from a rect light's centre that bounds a box, and the
// occluder-map window (axis-aligned with the light, texels of its aspect ratio up to 2:1) that the
// light depth maps of `ssm` and `bitmask` are rendered through.
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
    // The projection through the window, clipping a little outside [near, far].
    glm::mat4 viewProj(const scene::RectLight& light) const;
};

// Tangent of the widest half-angle of a light-centred view: 80 degrees from the light's axis.
inline constexpr float kMaxViewTan = 5.67f;

// The vertices, in the frame of a view from ORIGIN (a point of the light's plane) along the
// light's axes (x along right(), y along upAxis(), z along forward()), of the part of each box
// inside the widest view (|x|, |y| <= kMaxViewTan z): what such a view can hold. A box that
// reaches behind or beside the light is cut there, so the parts no map holds set no near plane.
std::vector<glm::vec3> visibleVertices(Boxes boxes, const scene::RectLight& light,
                                       const glm::vec3& origin);

// The window that bounds BOXES seen from the light's centre (empty when none lies in front).
LightWindow windowOf(const scene::RectLight& light, Boxes boxes);

// The most a texel of the occluder map is stretched toward a long light's aspect ratio. Stretched
// all the way, a 1.5 x 0.015 light's casters fell between the texels of a 256 map (100:1): the
// shadows of tests/data/gl/adaptive_two_shadows.json under it came out 0.27 (`ssm`) and 0.30
// (`bitmask`) off `exact`, 0.013 with texels of 2:1, 0.012 and 0.013 with square ones.
inline constexpr float kMaxTexelAspect = 2.0f;

// The occluder-map window: the casters' window grown along one axis so that its aspect ratio,
// and so that of every texel of a square map, is the light's, up to kMaxTexelAspect (or 1 /
// it): a light of at most 2:1 is searched in square areas of texels.
LightWindow occluderWindow(const scene::RectLight& light, Boxes casters);

}  // namespace penumbra::passes
