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
#include "renderer/scene/gltf_primitive.h"

namespace penumbra::scene {
namespace {

struct Instance {
    int node;
    int mesh;
    glm::dmat4 world;
};

std::string nodeKey(int node) {
    return "nodes." + std::to_string(node);
}

bool allFinite(const std::vector<double>& values) {
    return std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); });
}

glm::dmat4 localMatrix(const GltfDocument& doc, int index) {
    const tinygltf::Node& node = doc.model.nodes[static_cast<std::size_t>(index)];
    const std::string key = nodeKey(index);
    auto check = [&](const std::vector<double>& v, const char* name, std::size_t size) {
        if (!v.empty() && v.size() != size)
            doc.fail(key + "." + name, "expected " + std::to_string(size) + " numbers");
        if (!allFinite(v)) doc.fail(key + "." + name, "non-finite value");
    };
    check(node.matrix, "matrix", 16);
    check(node.translation, "translation", 3);
    check(node.rotation, "rotation", 4);
    check(node.scale, "scale", 3);
    if (!node.matrix.empty()) {
        glm::dmat4 m(1.0);
        for (int i = 0; i < 16; ++i) m[i / 4][i % 4] = node.matrix[static_cast<std::size_t>(i)];
        return m;
    }
    glm::dmat4 m(1.0);
    if (!node.translation.empty())
        m = glm::translate(m, {node.translation[0], node.translation[1], node.translation[2]});
    if (!node.rotation.empty()) {
        glm::dquat q(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);
        const double length = glm::length(q);
        if (!(length > 0.0) || !std::isfinite(length))
            doc.fail(key + ".rotation", "not a rotation (zero quaternion)");
        m = m * glm::mat4_cast(q / length);
    }
    if (!node.scale.empty()) m = glm::scale(m, {node.scale[0], node.scale[1], node.scale[2]});
    return m;
}

// The nodes to draw from: the default scene's, else scene 0's, else every node no node parents.
std::vector<int> rootNodes(const GltfDocument& doc) {
    const auto& model = doc.model;
    const int count = static_cast<int>(model.nodes.size());
    for (int n = 0; n < count; ++n) {
        const tinygltf::Node& node = model.nodes[static_cast<std::size_t>(n)];
        for (std::size_t c = 0; c < node.children.size(); ++c)
            if (node.children[c] < 0 || node.children[c] >= count)
                doc.fail(nodeKey(n) + ".children." + std::to_string(c),
                         "node " + std::to_string(node.children[c]) + " does not exist");
        if (node.mesh >= static_cast<int>(model.meshes.size()))
            doc.fail(nodeKey(n) + ".mesh", "mesh " + std::to_string(node.mesh) + " does not exist");
    }
    int scene = model.defaultScene;
    if (scene >= static_cast<int>(model.scenes.size()))
        doc.fail("scene", "scene " + std::to_string(scene) + " does not exist");
    if (scene < 0 && !model.scenes.empty()) scene = 0;
    if (scene >= 0) {
        const auto& nodes = model.scenes[static_cast<std::size_t>(scene)].nodes;
        for (std::size_t i = 0; i < nodes.size(); ++i)
            if (nodes[i] < 0 || nodes[i] >= count)
                doc.fail("scenes." + std::to_string(scene) + ".nodes." + std::to_string(i),
                         "node " + std::to_string(nodes[i]) + " does not exist");
        return nodes;
    }
    std::vector<bool> is_child(static_cast<std::size_t>(count), false);
    for (const auto& node : model.nodes)
        for (int c : node.children) is_child[static_cast<std::size_t>(c)] = true;
    std::vector<int> roots;
    for (int n = 0; n < count; ++n)
        if (!is_child[static_cast<std::size_t>(n)]) roots.push_back(n);
    return roots;
}

// Depth-first walk without recursion (deep chains must not overflow the stack).
std::vector<Instance> collectInstances(const GltfDocument& doc) {
    enum class State { New, Open, Done };
    std::vector<State> state(doc.model.nodes.size(), State::New);
    struct Frame {
        int node;
        glm::dmat4 world;
        std::size_t next_child;
    };
    std::vector<Instance> instances;
    for (int root : rootNodes(doc)) {
        if (state[static_cast<std::size_t>(root)] != State::New)
            doc.fail(nodeKey(root), "reached twice in the node hierarchy (a node has one parent)");
        state[static_cast<std::size_t>(root)] = State::Open;
        std::vector<Frame> stack{{root, localMatrix(doc, root), 0}};
        while (!stack.empty()) {
            Frame& top = stack.back();
            const tinygltf::Node& node = doc.model.nodes[static_cast<std::size_t>(top.node)];
            if (top.next_child == 0 && node.mesh >= 0)
                instances.push_back({top.node, node.mesh, top.world});
            if (top.next_child == node.children.size()) {
                state[static_cast<std::size_t>(top.node)] = State::Done;
                stack.pop_back();
                continue;
            }
            const int child = node.children[top.next_child++];
            const State child_state = state[static_cast<std::size_t>(child)];
            if (child_state == State::Open)
                doc.fail(nodeKey(top.node) + ".children",
                         "cycle in the node hierarchy (node " + std::to_string(child) +
                             " is an ancestor of node " + std::to_string(top.node) + ")");
            if (child_state == State::Done)
                doc.fail(nodeKey(child),
                         "reached twice in the node hierarchy (a node has one parent)");
            state[static_cast<std::size_t>(child)] = State::Open;
            const glm::dmat4 world = top.world * localMatrix(doc, child);
            stack.push_back({child, world, 0});  // invalidates TOP
        }
    }
    return instances;
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

}  // namespace

std::shared_ptr<const Model> loadGltf(const std::filesystem::path& path) {
    const GltfDocument doc = readGltfDocument(path);
    const std::vector<Instance> instances = collectInstances(doc);
    checkSizeLimits(doc, instances);

    auto model = std::make_shared<Model>();
    model->source = path.string();
    MaterialTable materials(doc, *model);
    std::map<std::pair<int, int>, PrimitiveGeometry> geometry;  // read once per primitive
    std::size_t triangles = 0;
    for (const Instance& instance : instances) {
        const double det = glm::determinant(glm::dmat3(instance.world));
        if (!std::isfinite(det)) doc.fail(nodeKey(instance.node), "transform overflows");
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

}  // namespace penumbra::scene
