// glTF to Model: the node hierarchy walked (cycles and shared nodes refused), sizes checked
// against the limits before reading, primitives read once and baked into each instance.
#include "renderer/scene/gltf_loader.h"

#include <algorithm>
#include <cmath>
#include <map>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include "renderer/scene/gltf_document.h"
#include "renderer/scene/gltf_material.h"
#include "renderer/scene/gltf_nodes.h"
#include "renderer/scene/gltf_primitive.h"

namespace penumbra::scene {
namespace {

struct Instance {
    int node;
    int mesh;
    glm::dmat4 world;
};

// The nodes that draw a mesh, with their world transforms.
std::vector<Instance> collectInstances(const GltfDocument& doc,
                                       const std::vector<GltfNodeVisit>& visits) {
    std::vector<Instance> instances;
    for (const GltfNodeVisit& visit : visits) {
        const int mesh = doc.model.nodes[static_cast<std::size_t>(visit.node)].mesh;
        if (mesh >= 0) instances.push_back({visit.node, mesh, visit.world});
    }
    return instances;
}

Bounds boundsOf(const Model& model) {
    Bounds b{glm::vec3(INFINITY), glm::vec3(-INFINITY)};
    for (const Mesh& mesh : model.meshes)
        for (const glm::vec3& p : mesh.positions) {
            b.min = glm::min(b.min, p);
            b.max = glm::max(b.max, p);
        }
    return b;
}

Mesh bake(const PrimitiveGeometry& g, const glm::dmat4& world, int material) {
    Mesh mesh;
    mesh.material = material;
    const glm::dmat3 normal_matrix = glm::transpose(glm::inverse(glm::dmat3(world)));
    mesh.positions.reserve(g.positions.size());
    mesh.normals.reserve(g.normals.size());
    for (const glm::vec3& p : g.positions) mesh.positions.emplace_back(world * glm::dvec4(p, 1.0));
    for (const glm::vec3& n : g.normals) {
        const glm::dvec3 t = normal_matrix * glm::dvec3(n);
        const double length = glm::length(t);
        mesh.normals.push_back(length > 0.0 ? glm::vec3(t / length) : n);
    }
    mesh.uvs = g.uvs;
    mesh.indices = g.indices;
    if (glm::determinant(glm::dmat3(world)) < 0.0)  // mirrored: keep front faces counter-clockwise
        for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3)
            std::swap(mesh.indices[t + 1], mesh.indices[t + 2]);
    return mesh;
}

// The size limits, from the accessors' counts, before any geometry is read.
void checkSizeLimits(const GltfDocument& doc, const std::vector<Instance>& instances) {
    std::size_t vertices = 0;
    std::size_t triangles = 0;
    for (const Instance& instance : instances) {
        const auto& mesh = doc.model.meshes[static_cast<std::size_t>(instance.mesh)];
        for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
            const PrimitiveSize size = primitiveSize(doc, instance.mesh, static_cast<int>(p));
            vertices += size.vertices;
            triangles += size.triangles;
        }
        if (triangles > kMaxGltfTriangles || vertices > kMaxGltfVertices)
            doc.fail("", "too large: more than " + std::to_string(kMaxGltfTriangles) +
                             " triangles or " + std::to_string(kMaxGltfVertices) +
                             " vertices over all node instances");
    }
}

// The model of DOC's mesh-drawing nodes among VISITS.
std::shared_ptr<const Model> buildModel(const GltfDocument& doc,
                                        const std::vector<GltfNodeVisit>& visits,
                                        const std::filesystem::path& path) {
    const std::vector<Instance> instances = collectInstances(doc, visits);
    checkSizeLimits(doc, instances);

    auto model = std::make_shared<Model>();
    model->source = path.string();
    MaterialTable materials(doc, *model);
    std::map<std::pair<int, int>, PrimitiveGeometry> geometry;  // read once per primitive
    std::size_t triangles = 0;
    for (const Instance& instance : instances) {
        const double det = glm::determinant(glm::dmat3(instance.world));
        if (!std::isfinite(det)) doc.fail(gltfNodeKey(instance.node), "transform overflows");
        if (det == 0.0) continue;  // scaled to nothing: nothing to draw
        const auto& mesh = doc.model.meshes[static_cast<std::size_t>(instance.mesh)];
        for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
            const auto id = std::make_pair(instance.mesh, static_cast<int>(p));
            auto cached = geometry.find(id);
            if (cached == geometry.end())
                cached =
                    geometry.emplace(id, readPrimitive(doc, id.first, id.second, kMaxGltfTriangles))
                        .first;
            const PrimitiveGeometry& g = cached->second;
            if (g.indices.empty()) continue;
            triangles += g.indices.size() / 3;  // Draco may hold more than its accessors said
            if (triangles > kMaxGltfTriangles)
                doc.fail(
                    "", "too large: more than " + std::to_string(kMaxGltfTriangles) + " triangles");
            const std::string key = "meshes." + std::to_string(id.first) + ".primitives." +
                                    std::to_string(p) + ".material";
            const int material = materials.indexOf(mesh.primitives[p].material, key);
            model->meshes.push_back(bake(g, instance.world, material));
        }
    }
    if (model->meshes.empty()) doc.fail("", "no triangles to draw in the glTF scene");
    return model;
}

}  // namespace

std::shared_ptr<const Model> loadGltf(const std::filesystem::path& path) {
    return loadGltfFile(path)->model;
}

std::shared_ptr<const GltfFile> loadGltfFile(const std::filesystem::path& path) {
    const GltfDocument doc = readGltfDocument(path);
    const std::vector<GltfNodeVisit> visits = walkGltfNodes(doc);
    auto file = std::make_shared<GltfFile>();
    file->label = doc.label;
    file->model = buildModel(doc, visits, path);
    file->bounds = boundsOf(*file->model);
    file->cameras = doc.cameras;
    file->lights = doc.lights;
    file->external_files = doc.external_files;
    for (const GltfNodeVisit& visit : visits) {
        const auto n = static_cast<std::size_t>(visit.node);
        if (n < doc.node_camera.size() && doc.node_camera[n] >= 0)
            file->placed_cameras.push_back({doc.node_camera[n], visit.node, visit.world});
        if (n < doc.node_light.size() && doc.node_light[n] >= 0)
            file->placed_lights.push_back({doc.node_light[n], visit.node, visit.world});
    }
    return file;
}

}  // namespace penumbra::scene
