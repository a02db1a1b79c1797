// Internal to the glTF loader: a .gltf/.glb file checked and parsed into tinygltf's model, with
// Draco-compressed primitives set aside for gltf_draco.cpp.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "renderer/scene/gltf_views.h"
#include "renderer/scene/tinygltf_include.h"

namespace penumbra::scene {

constexpr std::size_t kMaxGltfFileBytes = std::size_t{1} << 30;  // .gltf/.glb/.bin/image files

// A primitive's KHR_draco_mesh_compression extension.
struct DracoReference {
    int buffer_view = -1;
    int indices = -1;  // the primitive's indices accessor (its count sizes the mesh early)
    std::map<std::string, int> attributes;  // glTF attribute name -> Draco unique id
};

struct GltfDocument {
    std::string label;  // the file path as given: the start of every error message
    tinygltf::Model model;
    std::map<std::pair<int, int>, DracoReference> draco;  // by (mesh, primitive)
    std::vector<GltfCamera> cameras;
    std::vector<GltfPunctualLight> lights;
    std::vector<int> node_camera;  // per node: its camera index, or -1
    std::vector<int> node_light;   // per node: its KHR_lights_punctual light index, or -1
    // The files read besides the glTF itself (external buffers and images), as
    // AssetStore::pathKey names them.
    std::vector<std::string> external_files;

    // Throws InputError("<label>: <key>: <what>").
    [[noreturn]] void fail(const std::string& key, const std::string& what) const;
};

// Reads PATH (.gltf or .glb, told apart by content). Throws InputError.
GltfDocument readGltfDocument(const std::filesystem::path& path);

// Type checks on the JSON fields the loader reads (tinygltf 2.7 reads a wrongly typed field as
// absent) and on bufferView ranges against their buffers. Throws InputError naming the key.
void checkGltfJson(const nlohmann::json& doc, const std::string& label);

// Reads the cameras, the KHR_lights_punctual lights and the nodes' references to them from the
// document's JSON into DOC, every value checked (gltf_views.cpp). Throws InputError naming the key.
void readCamerasAndLights(const nlohmann::json& json, GltfDocument& doc);

}  // namespace penumbra::scene
