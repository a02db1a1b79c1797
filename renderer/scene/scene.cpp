// Derived geometry of scene values.
#include "renderer/scene/scene.h"

namespace penumbra::scene {

std::array<glm::vec3, 4> RectLight::corners() const {
    const glm::vec3 r = right() * (0.5f * size.x);
    const glm::vec3 u = upAxis() * (0.5f * size.y);
    return {position - r - u, position + r - u, position + r + u, position - r + u};
}

}  // namespace penumbra::scene
