// Light-centred views: see light_windows.h.
#include "renderer/passes/light_windows.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>

#include <glm/gtc/matrix_transform.hpp>

namespace penumbra::passes {
namespace {

// A vertex of a convex polytope and the faces it lies on (bits 0-5 a box's, 6-9 the cuts').
struct Vertex {
    glm::vec3 p;
    std::uint32_t faces;
};

// Cuts the polytope of vertices V to dot(N, p) >= 0 (plane bit BIT): the vertices inside, and
// where an edge (two vertices sharing two faces) crosses the plane, its crossing.
void cut(std::vector<Vertex>& v, const glm::vec3& n, std::uint32_t bit) {
    std::vector<float> d(v.size());
    for (size_t i = 0; i < v.size(); ++i) d[i] = glm::dot(n, v[i].p);
    std::vector<Vertex> out;
    for (size_t i = 0; i < v.size(); ++i)
        if (d[i] >= 0.0f) out.push_back({v[i].p, v[i].faces | (d[i] == 0.0f ? bit : 0u)});
    for (size_t i = 0; i < v.size(); ++i)
        for (size_t j = 0; j < v.size(); ++j) {
            const std::uint32_t shared = v[i].faces & v[j].faces;
            if (d[i] > 0.0f && d[j] < 0.0f && std::popcount(shared) >= 2)
                out.push_back({glm::mix(v[i].p, v[j].p, d[i] / (d[i] - d[j])), shared | bit});
        }
    v = std::move(out);
}

}  // namespace

glm::mat4 LightWindow::viewProj(const scene::RectLight& light) const {
    const glm::vec3 f = light.forward();
    const glm::mat4 view = glm::lookAt(light.position, light.position + f, light.upAxis());
    const glm::vec2 hi = lo + size;
    // The clip planes lie 0.1 % outside [near, far]: windowOf puts the near plane at the nearest
    // caster's face, and rounding clipped that face away at some scales (box_floating scaled
    // by 26 or 30: `css`'s map held the box's bottom under its top, which shadowed itself).
    // The maps' depths are linear from near (light_depth.vert), so only the clipping moves.
    const float n = near * (1.0f - 1e-3f), clip_far = far * (1.0f + 1e-3f);
    return glm::frustum(lo.x * n, hi.x * n, lo.y * n, hi.y * n, n, clip_far) * view;
}

std::vector<glm::vec3> visibleVertices(Boxes boxes, const scene::RectLight& light,
                                       const glm::vec3& origin) {
    const glm::vec3 f = light.forward(), r = light.right(), u = light.upAxis();
    const float k = kMaxViewTan;
    const glm::vec3 sides[4] = {{1, 0, k}, {-1, 0, k}, {0, 1, k}, {0, -1, k}};
    std::vector<glm::vec3> out;
    std::vector<Vertex> v;
    for (const WorldBox& b : boxes) {
        if (b.empty()) continue;
        v.clear();
        bool inside = true;
        for (int i = 0; i < 8; ++i) {
            const glm::vec3 d = b.corner(i) - origin;
            const glm::vec3 p(glm::dot(d, r), glm::dot(d, u), glm::dot(d, f));
            inside &= std::max(std::fabs(p.x), std::fabs(p.y)) <= k * p.z;
            // Corner i lies on the faces min or max of each axis (bits 2 * axis + 0 or 1).
            v.push_back(
                {p, (1u << (i & 1)) | (1u << (2 + ((i >> 1) & 1))) | (1u << (4 + ((i >> 2) & 1)))});
        }
        for (std::uint32_t s = 0; s < 4 && !inside && !v.empty(); ++s)
            cut(v, sides[s], 1u << (6 + s));
        for (const Vertex& x : v) out.push_back(x.p);
    }
    return out;
}

LightWindow windowOf(const scene::RectLight& light, Boxes boxes) {
    LightWindow w;
    const std::vector<glm::vec3> points = visibleVertices(boxes, light, light.position);
    float zmin = 1e30f, zmax = 0.0f;
    for (const auto& p : points) zmin = std::min(zmin, p.z), zmax = std::max(zmax, p.z);
    if (zmax <= 0.0f) return w;
    w.near = std::max(zmin, zmax * 1e-4f);
    w.far = zmax * 1.0001f + 1e-5f;
    glm::vec2 lo(1e30f), hi(-1e30f);
    for (const auto& p : points) {
        const glm::vec2 t = glm::vec2(p) / std::max(p.z, w.near);
        lo = glm::min(lo, t), hi = glm::max(hi, t);
    }
    lo = glm::clamp(lo, -kMaxViewTan, kMaxViewTan), hi = glm::clamp(hi, -kMaxViewTan, kMaxViewTan);
    w.lo = lo, w.size = hi - lo;
    return w;
}

LightWindow occluderWindow(const scene::RectLight& light, Boxes casters) {
    LightWindow w = windowOf(light, casters);
    if (w.empty()) return w;
    const float aspect =
        std::clamp(light.size.x / light.size.y, 1.0f / kMaxTexelAspect, kMaxTexelAspect);
    const glm::vec2 centre = w.lo + 0.5f * w.size;
    if (w.size.x < w.size.y * aspect)
        w.size.x = w.size.y * aspect;
    else
        w.size.y = w.size.x / aspect;
    w.lo = centre - 0.5f * w.size;
    return w;
}

}  // namespace penumbra::passes
