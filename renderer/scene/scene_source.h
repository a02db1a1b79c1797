// Loading a scene file: JSON + -D overrides -> validated values, assets loaded once, and the
// animation applied per frame. Every input error ends here as an InputError naming file and key.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "renderer/scene/gltf_scene.h"
#include "renderer/scene/scene.h"

namespace penumbra::scene {

// One -D/--set KEY=VALUE. VALUE is JSON; a bare word that is not JSON is a string.
struct Override {
    std::string key;    // dotted path, e.g. "lights.0.size"
    std::string value;  // the text after '='
};

struct LoadOptions {
    int max_image_size = 16384;  // image.width/height limit (the renderer lowers it to GL's)
    std::optional<std::string> technique;  // -t NAME: replaces technique.name (see README)
    GltfSceneOptions gltf;  // --light-size, --no-floor: when the file is a .gltf/.glb
};

class SceneSource {
public:
    // Reads and validates FILE with OVERRIDES applied (a .gltf/.glb FILE: the scene that
    // gltfSceneFor makes of it, framed for the image size the overrides give) (including every
    // animation key frame), loads every glTF and the environment image once. Throws InputError.
    static SceneSource load(const std::filesystem::path& file,
                            const std::vector<Override>& overrides,
                            const LoadOptions& options = {});

    // The scene at FRAME: animation tracks interpolated linearly between keys, held outside.
    Scene at(int frame) const;

    // The scene's "animation.frames" spec, if any (already validated).
    const std::optional<std::string>& animationFrames() const { return animation_frames_; }
    const std::filesystem::path& path() const { return path_; }
    // The files the scene was read from, as AssetStore::pathKey names them: the scene file, then
    // every glTF (with the buffers and images it read from files) and environment image it
    // loaded (a render must not overwrite any of them).
    std::vector<std::string> inputFiles() const;
    // The document after overrides, before animation (for output headers and hashing).
    const nlohmann::json& document() const { return document_; }

private:
    std::filesystem::path path_;
    nlohmann::json document_;
    std::optional<std::string> animation_frames_;
    struct Track;
    std::vector<std::shared_ptr<const Track>> tracks_;
    struct AssetCache;
    std::shared_ptr<AssetCache> assets_;
};

}  // namespace penumbra::scene
