// Closed-surface test for models: see mesh_topology.h.
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

// Positions welded through a grid of cells of the weld distance from the corner LO of their
// bounds (at most 1 / kWeld cells a side): a point joins a welded one within that distance in
// its own cell or one of the 26 around it, else starts a new one.
class Welder {
public:
    Welder(const glm::vec3& lo, float distance) : lo_(lo), cell_(distance) {}

    std::uint32_t weld(const glm::vec3& p) {
        const glm::ivec3 c = cellOf(p);
        for (int dz = -1; dz <= 1; ++dz)
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const auto it = cells_.find(key(c + glm::ivec3(dx, dy, dz)));
                    if (it == cells_.end()) continue;
                    for (std::uint32_t w : it->second)
                        if (glm::all(
                                glm::lessThanEqual(glm::abs(welded_[w] - p), glm::vec3(cell_))))
                            return w;
                }
        const auto w = static_cast<std::uint32_t>(welded_.size());
        welded_.push_back(p);
        cells_[key(c)].push_back(w);
        return w;
    }

private:
    glm::vec3 lo_;
    float cell_;
    std::vector<glm::vec3> welded_;
    std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> cells_;

    glm::ivec3 cellOf(const glm::vec3& p) const {
        return glm::ivec3(glm::floor((p - lo_) / cell_));
    }
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
    Welder welder(lo, kWeld * size);
    // Per undirected edge (smaller welded index first): walks from smaller to larger minus
    // walks the other way.
    std::unordered_map<std::uint64_t, long> balance;
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

}  // namespace penumbra::scene
