// Light-centred views: see light_windows.h.
#include "renderer/passes/light_windows.h"

#include <algorithm>

#include <glm/gtc/matrix_transform.hpp>

namespace penumbra::passes {
namespace {
constexpr float kMaxTan = 5.67f;  // widest half-angle of a view: 80 degrees
}

glm::mat4 LightWindow::viewProj(const scene::RectLight& light) const {
    const glm::vec3 f = light.forward();
    const glm::mat4 view = glm::lookAt(light.position, light.position + f, light.upAxis());
    const glm::vec2 hi = lo + size;
    return glm::frustum(lo.x * near, hi.x * near, lo.y * near, hi.y * near, near, far) * view;
}

LightWindow windowOf(const scene::RectLight& light, const Bounds& bounds) {
    LightWindow w;
    if (bounds.empty()) return w;
    const glm::vec3 f = light.forward(), r = light.right(), u = light.upAxis();
    glm::vec3 corners[8];
    float zmin = 1e30f, zmax = -1e30f;
    for (int i = 0; i < 8; ++i) {
        corners[i] = bounds.corner(i) - light.position;
        const float z = glm::dot(corners[i], f);
        zmin = std::min(zmin, z), zmax = std::max(zmax, z);
    }
    if (zmax <= 0.0f) return w;
    w.near = std::max(zmin, zmax * 1e-4f);
    w.far = zmax * 1.0001f + 1e-5f;
    glm::vec2 lo(1e30f), hi(-1e30f);
    for (const auto& c : corners) {
        const float z = std::max(glm::dot(c, f), w.near);
        const glm::vec2 p(glm::dot(c, r) / z, glm::dot(c, u) / z);
        lo = glm::min(lo, p), hi = glm::max(hi, p);
    }
    lo = glm::clamp(lo, -kMaxTan, kMaxTan), hi = glm::clamp(hi, -kMaxTan, kMaxTan);
    w.lo = lo, w.size = hi - lo;
    return w;
}

LightWindow occluderWindow(const scene::RectLight& light, const Bounds& casters) {
    LightWindow w = windowOf(light, casters);
    if (w.empty()) return w;
    const float aspect = light.size.x / light.size.y;
    const glm::vec2 centre = w.lo + 0.5f * w.size;
    if (w.size.x < w.size.y * aspect)
        w.size.x = w.size.y * aspect;
    else
        w.size.y = w.size.x / aspect;
    w.lo = centre - 0.5f * w.size;
    return w;
}

}  // namespace penumbra::passes
