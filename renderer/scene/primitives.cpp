// Plane, box and UV sphere meshes, built with counter-clockwise front faces and outward unit
// normals (the winding the renderer culls with).
#include "renderer/scene/primitives.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/constants.hpp>

namespace penumbra::scene {
namespace {

// Appends a quad whose corners go counter-clockwise seen from the side NORMAL points to.
void addQuad(Mesh& mesh, const glm::vec3& normal, const glm::vec3 (&corners)[4]) {
    const auto base = static_cast<std::uint32_t>(mesh.positions.size());
    static constexpr glm::vec2 kUvs[4] = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};
    for (int i = 0; i < 4; ++i) {
        mesh.positions.push_back(corners[i]);
        mesh.normals.push_back(normal);
        mesh.uvs.push_back(kUvs[i]);
    }
    for (std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) mesh.indices.push_back(base + i);
}

}  // namespace

Mesh makePlane(const glm::vec2& size) {
    Mesh mesh;
    const float x = 0.5f * size.x;
    const float z = 0.5f * size.y;
    // Seen from +Y with X right and Z down the screen, (-x,+z) (+x,+z) (+x,-z) (-x,-z) is CCW.
    addQuad(mesh, {0, 1, 0}, {{-x, 0, z}, {x, 0, z}, {x, 0, -z}, {-x, 0, -z}});
    return mesh;
}

Mesh makeBox(const glm::vec3& size) {
    Mesh mesh;
    const glm::vec3 h = 0.5f * size;
    // Each face: normal n, and axes u, v with u x v = n, so corners -u-v, +u-v, +u+v, -u+v are CCW.
    const glm::vec3 axes[6][3] = {
        {{1, 0, 0}, {0, 0, -1}, {0, 1, 0}}, {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}},
        {{0, 1, 0}, {1, 0, 0}, {0, 0, -1}}, {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}},
        {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}},  {{0, 0, -1}, {-1, 0, 0}, {0, 1, 0}},
    };
    for (const auto& [n, u, v] : axes) {
        const glm::vec3 c = n * h;
        const glm::vec3 du = u * h;
        const glm::vec3 dv = v * h;
        addQuad(mesh, n, {c - du - dv, c + du - dv, c + du + dv, c - du + dv});
    }
    return mesh;
}

Mesh makeSphere(float radius, int segments) {
    Mesh mesh;
    const int rings = std::max(2, segments / 2);
    const float pi = glm::pi<float>();
    // Vertex grid (rings + 1) x (segments + 1): the seam column is duplicated for the uvs.
    for (int r = 0; r <= rings; ++r) {
        const float theta = pi * static_cast<float>(r) / static_cast<float>(rings);  // from +Y
        for (int s = 0; s <= segments; ++s) {
            const float phi = 2.0f * pi * static_cast<float>(s) / static_cast<float>(segments);
            const glm::vec3 n(std::sin(theta) * std::sin(phi), std::cos(theta),
                              std::sin(theta) * std::cos(phi));
            mesh.positions.push_back(radius * n);
            mesh.normals.push_back(n);
            mesh.uvs.emplace_back(static_cast<float>(s) / static_cast<float>(segments),
                                  static_cast<float>(r) / static_cast<float>(rings));
        }
    }
    const auto stride = static_cast<std::uint32_t>(segments + 1);
    for (int r = 0; r < rings; ++r) {
        for (int s = 0; s < segments; ++s) {
            const std::uint32_t a =
                static_cast<std::uint32_t>(r) * stride + static_cast<std::uint32_t>(s);
            const std::uint32_t b = a + stride;  // the next ring, towards -Y
            // phi grows counter-clockwise seen from +Y, so seen from outside (a, b, b+1) is CCW.
            if (r != 0) mesh.indices.insert(mesh.indices.end(), {a, b, a + 1});
            if (r != rings - 1) mesh.indices.insert(mesh.indices.end(), {a + 1, b, b + 1});
        }
    }
    return mesh;
}

}  // namespace penumbra::scene
