// Whether a model's triangles bound a solid (every edge met once each way) or include open
// sheets (a card, a floor), whose back faces are surfaces a light can see as well; and whether
// that solid is convex (nothing of it can shadow itself beyond a surface's tangent plane).
#pragma once

#include "renderer/scene/scene.h"

namespace penumbra::scene {

// True when, with vertices within 1e-5 of its size of each other taken as one, every edge of
// MODEL's non-degenerate triangles (over all its meshes) is walked as often in one direction as
// in the other: the surface closes, so a face turned away from a point outside lies behind one
// turned towards it.
// False for a plane, a box missing a face, or a model with no triangles.
bool isClosedSurface(const Model& model);

// True when MODEL is closed (isClosedSurface) and no vertex lies farther than 1e-4 of its size
// on the other side of any of its non-degenerate triangles' planes than the rest: the boundary
// of one convex solid (the built-in box and sphere; not the duck, nor two boxes in one model).
// Models whose triangles times vertices exceed kConvexTestBudget are taken as not convex.
inline constexpr double kConvexTestBudget = 4e7;
bool isConvexSurface(const Model& model);
// isConvexSurface() of a model isClosedSurface() already called closed: its vertex test alone,
// so the upload welds a model once.
bool isConvexGivenClosed(const Model& closed_model);

}  // namespace penumbra::scene
