// Closed- and convex-surface tests for models: see mesh_topology.h.
#include "renderer/scene/mesh_topology.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace penumbra::scene {
namespace {

// Vertices within kWeld of the model's bounding diagonal are one: seams repeat a position with
// other normals or uvs, often not to the bit (a sphere's seam at 2 pi, its poles).
constexpr float kWeld = 1e-5f;

// Positions welded through a grid of cells twice the weld distance D wide, from the corner LO
// of their bounds (at most 1 / (2 kWeld) cells a side): a point joins a welded one within D,
// which lies in its own cell or the next one on the nearer side along each axis (8 cells), else
// starts a new one. Each cell's welded points are a list through next_.
class Welder {
public:
    Welder(const glm::vec3& lo, float distance, std::size_t points)
        : lo_(lo), distance_(distance), cell_(2.0f * distance) {
        welded_.reserve(points);
        next_.reserve(points);
        heads_.reserve(points);
    }

    std::uint32_t weld(const glm::vec3& p) {
        const glm::vec3 t = (p - lo_) / cell_;
        const glm::ivec3 c(glm::floor(t));
        // Towards the nearer neighbour along each axis
        const glm::ivec3 side(t.x - float(c.x) < 0.5f ? -1 : 1, t.y - float(c.y) < 0.5f ? -1 : 1,
                              t.z - float(c.z) < 0.5f ? -1 : 1);
        for (int i = 0; i < 8; ++i) {
            const glm::ivec3 q = c + glm::ivec3(i & 1, (i >> 1) & 1, (i >> 2) & 1) * side;
            const auto it = heads_.find(key(q));
            for (std::uint32_t w = it == heads_.end() ? kNone : it->second; w != kNone;
                 w = next_[w])
                if (glm::all(glm::lessThanEqual(glm::abs(welded_[w] - p), glm::vec3(distance_))))
                    return w;
        }
        const auto w = static_cast<std::uint32_t>(welded_.size());
        welded_.push_back(p);
        auto [head, fresh] = heads_.try_emplace(key(c), w);
        next_.push_back(fresh ? kNone : head->second);
        head->second = w;
        return w;
    }

private:
    static constexpr std::uint32_t kNone = ~0u;
    glm::vec3 lo_;
    float distance_, cell_;
    std::vector<glm::vec3> welded_;
    std::vector<std::uint32_t> next_;  // the next welded point of the same cell
    std::unordered_map<std::uint64_t, std::uint32_t> heads_;  // per cell, its last welded point

    static std::uint64_t key(const glm::ivec3& c) {
        const auto part = [](int v) { return static_cast<std::uint64_t>(v) & 0x1fffffu; };
        return part(c.x) | (part(c.y) << 21) | (part(c.z) << 42);
    }
};

}  // namespace

bool isClosedSurface(const Model& model) {
    glm::vec3 lo(1e30f), hi(-1e30f);
    for (const Mesh& mesh : model.meshes)
        for (const glm::vec3& p : mesh.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
    // No mesh, or no area anywhere at float precision.
    const float size = glm::length(hi - lo);
    if (!(kWeld * size > 0.0f && std::isfinite(size))) return false;
    std::size_t points = 0, indices = 0;
    for (const Mesh& mesh : model.meshes)
        points += mesh.positions.size(), indices += mesh.indices.size();
    Welder welder(lo, kWeld * size, points);
    // Per undirected edge (smaller welded index first): walks from smaller to larger minus
    // walks the other way.
    std::unordered_map<std::uint64_t, long> balance;
    balance.reserve(indices);
    for (const Mesh& mesh : model.meshes) {
        std::vector<std::uint32_t> weld(mesh.positions.size());
        for (std::size_t i = 0; i < mesh.positions.size(); ++i)
            weld[i] = welder.weld(mesh.positions[i]);
        for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
            const std::uint32_t v[3] = {weld[mesh.indices[t]], weld[mesh.indices[t + 1]],
                                        weld[mesh.indices[t + 2]]};
            if (v[0] == v[1] || v[1] == v[2] || v[2] == v[0]) continue;  // no area
            for (int e = 0; e < 3; ++e) {
                const std::uint32_t a = v[e], b = v[(e + 1) % 3];
                balance[(std::uint64_t{std::min(a, b)} << 32) | std::max(a, b)] += a < b ? 1 : -1;
            }
        }
    }
    if (balance.empty()) return false;
    for (const auto& [edge, walks] : balance)
        if (walks != 0) return false;
    return true;
}

bool isConvexSurface(const Model& model) {
    return isClosedSurface(model) && isConvexGivenClosed(model);
}

bool isConvexGivenClosed(const Model& model) {
    glm::vec3 lo(1e30f), hi(-1e30f);
    double triangles = 0, points = 0;
    for (const Mesh& mesh : model.meshes) {
        for (const glm::vec3& p : mesh.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
        triangles += double(mesh.indices.size() / 3), points += double(mesh.positions.size());
    }
    if (triangles * points > kConvexTestBudget) return false;
    const float tolerance = 1e-4f * glm::length(hi - lo);
    for (const Mesh& mesh : model.meshes)
        for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
            const glm::vec3 a = mesh.positions[mesh.indices[t]];
            const glm::vec3 n = glm::cross(mesh.positions[mesh.indices[t + 1]] - a,
                                           mesh.positions[mesh.indices[t + 2]] - a);
            const float length = glm::length(n);
            if (!(length > 0.0f)) continue;  // no area
            // Every vertex on one side of the plane (either: the winding may face inwards).
            bool above = false, below = false;
            for (const Mesh& other : model.meshes)
                for (const glm::vec3& p : other.positions) {
                    const float h = glm::dot(n, p - a) / length;
                    above = above || h > tolerance;
                    below = below || h < -tolerance;
                    if (above && below) return false;
                }
        }
    return true;
}

}  // namespace penumbra::scene
