// Composition of object transforms from translate/rotate/scale and the checks a given matrix
// must pass (finite, affine, invertible in float).
#include "renderer/scene/transform.h"

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace penumbra::scene {

glm::mat4 composeTransform(const glm::vec3& translate, const glm::vec3& rotate_degrees,
                           const glm::vec3& scale) {
    const glm::mat4 identity(1.0f);
    const glm::mat4 t = glm::translate(identity, translate);
    const glm::mat4 rx = glm::rotate(identity, glm::radians(rotate_degrees.x), {1, 0, 0});
    const glm::mat4 ry = glm::rotate(identity, glm::radians(rotate_degrees.y), {0, 1, 0});
    const glm::mat4 rz = glm::rotate(identity, glm::radians(rotate_degrees.z), {0, 0, 1});
    const glm::mat4 s = glm::scale(identity, scale);
    return t * rz * ry * rx * s;
}

const char* matrixProblem(const glm::mat4& matrix) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(matrix[c][r])) return "not finite";
    if (matrix[0][3] != 0.0f || matrix[1][3] != 0.0f || matrix[2][3] != 0.0f ||
        matrix[3][3] != 1.0f)
        return "not affine (its last row must be 0 0 0 1)";
    const double det = glm::determinant(glm::dmat3(glm::mat3(matrix)));
    if (!std::isfinite(det) || det == 0.0) return "not invertible";
    // Normals use the inverse transpose in float: it must exist there too.
    const glm::mat3 inverse = glm::inverse(glm::mat3(matrix));
    for (int c = 0; c < 3; ++c)
        for (int r = 0; r < 3; ++r)
            if (!std::isfinite(inverse[c][r])) return "not invertible";
    return "";
}

}  // namespace penumbra::scene
