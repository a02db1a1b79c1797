// Whether a model's triangles bound a solid (every edge met once each way) or include open
// sheets (a card, a floor), whose back faces are surfaces a light can see as well.
#pragma once

#include "renderer/scene/scene.h"

namespace penumbra::scene {

// True when, with vertices within 1e-5 of its size of each other taken as one, every edge of
// MODEL's non-degenerate triangles (over all its meshes) is walked as often in one direction as
// in the other: the surface closes, so a face turned away from a point outside lies behind one
// turned towards it.
// False for a plane, a box missing a face, or a model with no triangles.
bool isClosedSurface(const Model& model);

}  // namespace penumbra::scene
