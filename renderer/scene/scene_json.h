// Validating a scene document (after -t/-D and animation) into a Scene: every key checked for
// type, range and consistency, unknown keys refused, assets taken from an AssetStore.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "renderer/core/json_field.h"
#include "renderer/scene/asset_store.h"
#include "renderer/scene/gltf_loader.h"
#include "renderer/scene/scene.h"

namespace penumbra::scene {

constexpr const char* kSceneFormat = "penumbra-scene/1";
constexpr int kMaxImageSize = 16384;  // image.width/height limit before the GL's

struct SceneContext {
    std::string file;                    // the scene path as given: the start of every error
    std::filesystem::path folder;        // relative asset paths resolve against it
    std::string default_name;            // the file's stem
    int max_image_size = kMaxImageSize;  // image.width/height limit
    AssetStore* assets = nullptr;
};

// Throws InputError("<file>: <dotted key>: <what is wrong>").
Scene buildScene(const nlohmann::json& doc, const SceneContext& context);

// The "objects" array, and its element INDEX (object_json.cpp).
std::vector<Object> buildObjects(const Field& objects, const SceneContext& context);
Object buildObject(const Field& object, std::size_t index, const SceneContext& context);

// True when directions A and B are parallel (or opposite), to 1e-6.
bool parallelDirections(const glm::vec3& a, const glm::vec3& b);

// The "camera" block (camera_json.cpp); FAR_AUTO is set when a glTF camera's zfar is infinite.
Camera readCamera(const Field& f, const SceneContext& context, bool& far_auto);
// The world bounds of OBJECTS' vertices (for a glTF camera with an infinite zfar).
Bounds objectBounds(const std::vector<Object>& objects);

// The "lights" array and its one element (light_json.cpp): a rect light, or a glTF's lights.
std::vector<RectLight> readLights(const Field& f, const SceneContext& context);
std::vector<RectLight> readLight(const Field& f, const SceneContext& context);

// The glTF file that FIELD (a string path) names, loaded once per scene; fails at FIELD.
std::shared_ptr<const GltfFile> readGltfReference(const Field& field, const SceneContext& context);

// The top-level block that holds dotted key PARTS and checks on its own: ["camera"], ["image"],
// ["environment"], ["technique"], ["lights", "N"] or ["objects", "N"] (empty for other keys).
std::vector<std::string> scenePartOf(const std::vector<std::string>& parts);

// Checks VALUE as the block at PART (scenePartOf's result) as buildScene would, alone: the
// blocks' checks do not depend on each other. Throws InputError like buildScene.
void checkScenePart(const nlohmann::json& value, const std::vector<std::string>& part,
                    const SceneContext& context);

// PATH resolved against the scene's folder when relative.
std::filesystem::path resolveAsset(const SceneContext& context, const std::string& path);

}  // namespace penumbra::scene
