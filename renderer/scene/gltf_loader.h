// Loading a glTF 2.0 file (.gltf or .glb, Draco included) into a flattened Model: the scene's
// node transforms baked into the meshes, base colours and base-colour textures kept.
#pragma once

#include <cstddef>
#include <filesystem>
#include <memory>

#include "renderer/scene/scene.h"

namespace penumbra::scene {

constexpr std::size_t kMaxGltfTriangles = 20'000'000;  // over all node instances
constexpr std::size_t kMaxGltfVertices = 60'000'000;   // over all node instances

// Loads PATH. Every problem with the file is an InputError whose message starts with PATH and
// names the glTF key at fault ("x.glb: meshes.0.primitives.0.indices: index 36 out of range
// (24 vertices)"). The model has at least one triangle and one material.
std::shared_ptr<const Model> loadGltf(const std::filesystem::path& path);

}  // namespace penumbra::scene
