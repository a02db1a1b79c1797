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

std::vector<glm::vec3> cornersInFront(Boxes boxes, const glm::vec3& origin,
                                      const glm::vec3& forward) {
    std::vector<glm::vec3> out;
    out.reserve(boxes.size() * 8);
    for (const Bounds& b : boxes) {
        if (b.empty()) continue;
        glm::vec3 c[8];
        bool in_front = false;
        for (int i = 0; i < 8; ++i) {
            c[i] = b.corner(i) - origin;
            in_front |= glm::dot(c[i], forward) > 0.0f;
        }
        if (in_front) out.insert(out.end(), c, c + 8);
    }
    return out;
}

LightWindow windowOf(const scene::RectLight& light, Boxes boxes) {
    LightWindow w;
    const glm::vec3 f = light.forward(), r = light.right(), u = light.upAxis();
    const std::vector<glm::vec3> corners = cornersInFront(boxes, light.position, f);
    if (corners.empty()) return w;
    float zmin = 1e30f, zmax = -1e30f;
    for (const auto& c : corners) {
        const float z = glm::dot(c, f);
        zmin = std::min(zmin, z), zmax = std::max(zmax, z);
    }
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

LightWindow occluderWindow(const scene::RectLight& light, Boxes casters) {
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
