// Internal to the glTF loader: the node hierarchy of the glTF scene walked once, each node with
// its world transform, for meshes (gltf_loader.cpp) and for cameras and lights (gltf_loader.cpp).
#pragma once

#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "renderer/scene/gltf_document.h"

namespace penumbra::scene {

struct GltfNodeVisit {
    int node;
    glm::dmat4 world;  // model (glTF scene) space from the node's space
};

// Every node of the glTF scene (the default scene's, else scene 0's, else every node no node
// parents) in depth-first order with its world transform. Throws InputError naming the node key
// for a missing child, a cycle, a node reached twice or a non-finite or degenerate local matrix.
std::vector<GltfNodeVisit> walkGltfNodes(const GltfDocument& doc);

// "nodes.N".
std::string gltfNodeKey(int node);

}  // namespace penumbra::scene
