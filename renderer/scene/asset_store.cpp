// Load-once caches for a scene's assets (a glTF file's model, cameras and lights together),
// keyed by canonical path or by a derived model's parameters; one mutex, since SceneSource::at
// may be called from several threads.
#include "renderer/scene/asset_store.h"

#include "renderer/scene/environment_image.h"
#include "renderer/scene/gltf_loader.h"

namespace penumbra::scene {

std::string AssetStore::pathKey(const std::filesystem::path& path) {
    std::error_code ec;
    const std::filesystem::path canonical = std::filesystem::weakly_canonical(path, ec);
    return ec ? path.lexically_normal().string() : canonical.string();
}

std::shared_ptr<const Model> AssetStore::gltf(const std::filesystem::path& path) {
    return gltfFile(path)->model;
}

std::shared_ptr<const GltfFile> AssetStore::gltfFile(const std::filesystem::path& path) {
    const std::lock_guard lock(mutex_);
    auto& slot = gltf_[pathKey(path)];
    if (!slot) slot = loadGltfFile(path);
    return slot;
}

std::shared_ptr<const EnvironmentImage> AssetStore::environment(const std::filesystem::path& path) {
    const std::lock_guard lock(mutex_);
    auto& slot = environments_[pathKey(path)];
    if (!slot) slot = loadEnvironmentImage(path);
    return slot;
}

std::vector<std::string> AssetStore::files() {
    const std::lock_guard lock(mutex_);
    std::vector<std::string> out;
    for (const auto& [key, file] : gltf_) {
        out.push_back(key);
        out.insert(out.end(), file->external_files.begin(), file->external_files.end());
    }
    for (const auto& [key, image] : environments_) out.push_back(key);
    return out;
}

std::shared_ptr<const Model> AssetStore::derived(
    const std::string& key, const std::function<std::shared_ptr<const Model>()>& make) {
    const std::lock_guard lock(mutex_);
    if (const auto it = derived_.find(key); it != derived_.end()) return it->second;
    if (derived_.size() >= kMaxDerived) derived_.clear();
    auto model = make();
    derived_.emplace(key, model);
    return model;
}

}  // namespace penumbra::scene
