// Object transforms: translate/rotate/scale composed in the scene file's order, and checks that
// a given matrix is usable as a model-to-world transform.
#pragma once

#include <glm/glm.hpp>

namespace penumbra::scene {

// T * Rz * Ry * Rx * S: scale, then rotate about X, then Y, then Z (degrees), then translate.
glm::mat4 composeTransform(const glm::vec3& translate, const glm::vec3& rotate_degrees,
                           const glm::vec3& scale);

// Why MATRIX cannot be an object's transform ("" when it can): non-finite, not affine,
// or not invertible.
const char* matrixProblem(const glm::mat4& matrix);

}  // namespace penumbra::scene
