// The assets one scene file uses, each loaded or built once and shared: glTF models by path,
// environment images by path, and derived models (primitives, tinted glTF copies) by a key.
#pragma once

#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "renderer/scene/gltf_loader.h"
#include "renderer/scene/scene.h"

namespace penumbra::scene {

class AssetStore {
public:
    // loadGltf(PATH) the first time PATH (made canonical) is asked for. Throws its InputError.
    std::shared_ptr<const Model> gltf(const std::filesystem::path& path);
    // The whole file (model, bounds, cameras, lights), loaded once with gltf()'s model.
    std::shared_ptr<const GltfFile> gltfFile(const std::filesystem::path& path);
    // loadEnvironmentImage(PATH) the first time PATH is asked for. Throws its InputError.
    std::shared_ptr<const EnvironmentImage> environment(const std::filesystem::path& path);
    // MAKE() the first time KEY is asked for. At most kMaxDerived are kept (animated shapes make
    // a new one per frame); scenes hold their own references, so dropping one is safe.
    std::shared_ptr<const Model> derived(const std::string& key,
                                         const std::function<std::shared_ptr<const Model>()>& make);

    // The cache key of PATH: canonical when it exists, else lexically normal.
    static std::string pathKey(const std::filesystem::path& path);
    // The keys of every glTF (with the buffers and images it read from files) and environment
    // file loaded so far (what a render reads).
    std::vector<std::string> files();

private:
    static constexpr std::size_t kMaxDerived = 256;

    std::mutex mutex_;
    std::map<std::string, std::shared_ptr<const GltfFile>> gltf_;
    std::map<std::string, std::shared_ptr<const EnvironmentImage>> environments_;
    std::map<std::string, std::shared_ptr<const Model>> derived_;
};

}  // namespace penumbra::scene
