// The glTF scene's node hierarchy: roots chosen, each node's local matrix checked and composed
// into world transforms, walked depth-first without recursion (cycles and shared nodes refused).
#include "renderer/scene/gltf_nodes.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

namespace penumbra::scene {

std::string gltfNodeKey(int node) {
    return "nodes." + std::to_string(node);
}

namespace {

bool allFinite(const std::vector<double>& values) {
    return std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); });
}

glm::dmat4 localMatrix(const GltfDocument& doc, int index) {
    const tinygltf::Node& node = doc.model.nodes[static_cast<std::size_t>(index)];
    const std::string key = gltfNodeKey(index);
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
                doc.fail(gltfNodeKey(n) + ".children." + std::to_string(c),
                         "node " + std::to_string(node.children[c]) + " does not exist");
        if (node.mesh >= static_cast<int>(model.meshes.size()))
            doc.fail(gltfNodeKey(n) + ".mesh",
                     "mesh " + std::to_string(node.mesh) + " does not exist");
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

}  // namespace

// Depth-first walk without recursion (deep chains must not overflow the stack).
std::vector<GltfNodeVisit> walkGltfNodes(const GltfDocument& doc) {
    enum class State { New, Open, Done };
    std::vector<State> state(doc.model.nodes.size(), State::New);
    struct Frame {
        int node;
        glm::dmat4 world;
        std::size_t next_child;
    };
    std::vector<GltfNodeVisit> visits;
    for (int root : rootNodes(doc)) {
        if (state[static_cast<std::size_t>(root)] != State::New)
            doc.fail(gltfNodeKey(root),
                     "reached twice in the node hierarchy (a node has one parent)");
        state[static_cast<std::size_t>(root)] = State::Open;
        std::vector<Frame> stack{{root, localMatrix(doc, root), 0}};
        while (!stack.empty()) {
            Frame& top = stack.back();
            const tinygltf::Node& node = doc.model.nodes[static_cast<std::size_t>(top.node)];
            if (top.next_child == 0) visits.push_back({top.node, top.world});
            if (top.next_child == node.children.size()) {
                state[static_cast<std::size_t>(top.node)] = State::Done;
                stack.pop_back();
                continue;
            }
            const int child = node.children[top.next_child++];
            const State child_state = state[static_cast<std::size_t>(child)];
            if (child_state == State::Open)
                doc.fail(gltfNodeKey(top.node) + ".children",
                         "cycle in the node hierarchy (node " + std::to_string(child) +
                             " is an ancestor of node " + std::to_string(top.node) + ")");
            if (child_state == State::Done)
                doc.fail(gltfNodeKey(child),
                         "reached twice in the node hierarchy (a node has one parent)");
            state[static_cast<std::size_t>(child)] = State::Open;
            const glm::dmat4 world = top.world * localMatrix(doc, child);
            stack.push_back({child, world, 0});  // invalidates TOP
        }
    }
    return visits;
}

}  // namespace penumbra::scene
