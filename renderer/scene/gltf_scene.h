// A scene made from one glTF file: its first camera or a camera that frames the model, its
// KHR_lights_punctual lights as rect lights or one default light, and a floor. The conversions
// are shared by `render model.glb`, `scene model.glb` and a scene's {"gltf": ...} camera/lights.
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "renderer/scene/asset_store.h"
#include "renderer/scene/gltf_loader.h"
#include "renderer/scene/scene.h"

namespace penumbra::scene {

constexpr std::size_t kMaxGltfLights = 64;       // placed punctual lights taken from one file
constexpr float kFramingFovY = 40.0f;            // the framing camera's vertical field, degrees
constexpr float kFramingAzimuth = 30.0f;         // degrees from +Z toward +X
constexpr float kFramingElevation = 20.0f;       // degrees above the horizontal
constexpr float kFramingMargin = 1.1f;           // the bounding sphere's radius, enlarged by
constexpr float kFarMargin = 1.05f;              // far = this x the farthest covered point
constexpr float kPunctualLightSide = 0.25f;      // x the bounding radius: default light size
constexpr float kDefaultLightDistance = 3.0f;    // x the bounding radius from the centre
constexpr float kDefaultLightIrradiance = 2.5f;  // on axis at the centre (far-field)
constexpr float kDirectionalDistance = 3.0f;     // x the bounding radius from the centre
constexpr float kFloorSide = 20.0f;              // x the bounding radius
constexpr float kFloorAlbedo = 0.8f;

// `--light-size` and `--no-floor`.
struct GltfSceneOptions {
    std::optional<glm::vec2> light_size;  // metres; default by kind (see gltf_scene.cpp)
    bool floor = true;
};

// The model's bounds, checked usable for placing a camera and lights (finite, some extent).
// Throws InputError naming the file.
Bounds checkedBounds(const GltfFile& file);

// The first camera the glTF scene places (lowest camera index, then the first node), or null.
const GltfPlacement* firstPlacedCamera(const GltfFile& file);

// The glTF camera placed by PLACED as a Camera: yfov -> fov_y degrees, znear, zfar (absent:
// far covers COVER from the camera), the node's -Z as the view and +Y as up. Orthographic
// cameras are refused. Throws InputError naming the glTF key.
Camera cameraFromGltf(const GltfFile& file, const GltfPlacement& placed, const Bounds& cover);

// A camera that frames MODEL's bounding sphere at ASPECT (width / height) from the direction
// kFramingAzimuth / kFramingElevation; far covers COVER.
Camera framingCamera(const Bounds& model, float aspect, const Bounds& cover);

// Every placed punctual light of FILE as a rect light of SIZE (default: kPunctualLightSide x
// the bounding radius, square). Throws InputError naming the glTF key (too many lights, a
// degenerate node transform, an intensity beyond float range).
std::vector<RectLight> lightsFromGltf(const GltfFile& file, std::optional<glm::vec2> size);

// The light of a glTF without punctual lights, above the model (see gltf_scene.cpp).
RectLight defaultLight(const Bounds& model, std::optional<glm::vec2> size);

// The scene document `penumbra scene` writes (keys in reading order, each number the shortest
// decimal that reads back as the float computed) and `render model.glb` renders: NAME, the camera,
// IMAGE's size, the lights, the model (GLTF_PATH as written in the document) and the floor.
nlohmann::ordered_json gltfSceneDocument(const GltfFile& file, const std::string& gltf_path,
                                         const std::string& name, const GltfSceneOptions& options,
                                         const ImageSettings& image);

// True for a .gltf or .glb name (any case).
bool isGltfPath(const std::filesystem::path& path);

// The scene document of GLTF for a scene file at SCENE_FILE: the glTF named relative to its
// folder (by file name alone when SCENE_FILE is GLTF itself), checked by loading it with
// ASSETS (which keeps the glTF loaded). Throws InputError.
nlohmann::ordered_json gltfSceneFor(const std::filesystem::path& gltf,
                                    const std::filesystem::path& scene_file,
                                    const GltfSceneOptions& options, const ImageSettings& image,
                                    AssetStore& assets);

// The farthest point of BOX from FROM, times kFarMargin.
float coveringFar(const glm::vec3& from, const Bounds& box);

}  // namespace penumbra::scene
