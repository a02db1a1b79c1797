// Built-in shapes, centred at the origin, as indexed triangles with outward normals and uvs,
// counter-clockwise seen from outside.
#pragma once

#include <glm/glm.hpp>

#include "renderer/scene/scene.h"

namespace penumbra::scene {

constexpr int kMinSphereSegments = 3;
constexpr int kMaxSphereSegments = 1024;
constexpr int kDefaultSphereSegments = 32;

// In the XZ plane facing +Y, SIZE along X and Z.
Mesh makePlane(const glm::vec2& size);
// Edge lengths SIZE; flat faces (24 vertices, 12 triangles).
Mesh makeBox(const glm::vec3& size);
// UV sphere: SEGMENTS around the Y axis, max(2, SEGMENTS / 2) rings from pole to pole.
Mesh makeSphere(float radius, int segments);

}  // namespace penumbra::scene
