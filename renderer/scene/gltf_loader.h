// Loading a glTF 2.0 file (.gltf or .glb, Draco included) into a flattened Model: the scene's
// node transforms baked into the meshes, base colours and base-colour textures kept.
#pragma once

#include <cstddef>
#include <filesystem>
#include <memory>

#include "renderer/scene/gltf_views.h"
#include "renderer/scene/scene.h"

namespace penumbra::scene {

constexpr std::size_t kMaxGltfTriangles = 20'000'000;  // over all node instances
constexpr std::size_t kMaxGltfVertices = 60'000'000;   // over all node instances

// Loads PATH. Every problem with the file is an InputError whose message starts with PATH and
// names the glTF key at fault ("x.glb: meshes.0.primitives.0.indices: index 36 out of range
// (24 vertices)"). The model has at least one triangle and one material.
std::shared_ptr<const Model> loadGltf(const std::filesystem::path& path);

// An axis-aligned box (min <= max when built from at least one point).
struct Bounds {
    glm::vec3 min{0.0f};
    glm::vec3 max{0.0f};
    glm::vec3 center() const { return (min + max) * 0.5f; }
    float radius() const { return glm::length(max - min) * 0.5f; }  // of the enclosing sphere
};

// Everything a scene takes from one glTF file, read in one pass: the model, its bounds, and the
// cameras and punctual lights with the nodes of the glTF scene that place them (walk order).
struct GltfFile {
    std::string label;  // the path as given: the start of every error message
    std::shared_ptr<const Model> model;
    Bounds bounds;  // of every vertex of the model (glTF scene space)
    std::vector<GltfCamera> cameras;
    std::vector<GltfPunctualLight> lights;
    std::vector<GltfPlacement> placed_cameras;
    std::vector<GltfPlacement> placed_lights;
    std::vector<std::string> external_files;  // read besides the glTF (GltfDocument's)
};

// loadGltf's model with the rest of GltfFile. Throws InputError as loadGltf.
std::shared_ptr<const GltfFile> loadGltfFile(const std::filesystem::path& path);

}  // namespace penumbra::scene
