// SceneSource: the scene file read once (JSON, -t/-D, assets, animation checked at every key
// frame), then one validated Scene per frame built from the document with the tracks applied.
#include "renderer/scene/scene_source.h"

#include <map>
#include <set>

#include "renderer/core/error.h"
#include "renderer/core/json_field.h"
#include "renderer/scene/animation.h"
#include "renderer/scene/asset_store.h"
#include "renderer/scene/dotted_key.h"
#include "renderer/scene/json_file.h"
#include "renderer/scene/overrides.h"
#include "renderer/scene/scene_json.h"

namespace penumbra::scene {
namespace {

constexpr std::size_t kMaxSceneFileBytes = std::size_t{64} << 20;

// E's message without the leading "<file>: ", to be re-prefixed with more context.
std::string withoutFile(const InputError& e, const std::string& file) {
    std::string message = e.what();
    const std::string prefix = file + ": ";
    if (message.rfind(prefix, 0) == 0) message.erase(0, prefix.size());
    return message;
}

// An unknown key that a -D created is the flag's fault: "-D techniqe.samples: unknown key ...".
void blameOverride(const UnknownKeyError& e, const std::vector<Override>& overrides) {
    for (const Override& o : overrides)
        if (o.key == e.key() || o.key.rfind(e.key() + ".", 0) == 0)
            throw InputError("-D " + o.key + ": " + e.what_only());
}

// The image size the overrides give a default image (for framing a glTF's camera), or the
// default when they give none or a bad one (loading reports that one).
ImageSettings imageAfterOverrides(const std::vector<Override>& overrides) {
    ImageSettings image;
    nlohmann::json doc = {{"image", {{"width", image.width}, {"height", image.height}}}};
    std::vector<Override> image_overrides;  // the others may need keys this document lacks
    for (const Override& o : overrides)
        if (o.key == "image" || o.key.rfind("image.", 0) == 0) image_overrides.push_back(o);
    try {
        applyOverrides(doc, image_overrides);
    } catch (const InputError&) {
        return image;
    }
    const nlohmann::json* block = findAt(doc, {"image"});
    if (!block || !block->is_object()) return image;
    auto read = [&](const char* key, int& value) {
        const auto it = block->find(key);
        if (it != block->end() && it->is_number_integer() && it->get<long long>() >= 1 &&
            it->get<long long>() <= kMaxImageSize)
            value = it->get<int>();
    };
    read("width", image.width);
    read("height", image.height);
    return image;
}

}  // namespace

struct SceneSource::Track {
    AnimationTrack track;
};

struct SceneSource::AssetCache {
    AssetStore store;
    SceneContext context;
    std::shared_ptr<const Scene> still;  // the scene when nothing is animated
};

std::vector<std::string> SceneSource::inputFiles() const {
    std::vector<std::string> files{AssetStore::pathKey(path_)};
    for (std::string& f : assets_->store.files()) files.push_back(std::move(f));
    return files;
}

SceneSource SceneSource::load(const std::filesystem::path& file,
                              const std::vector<Override>& overrides, const LoadOptions& options) {
    const std::string label = file.string();
    SceneSource source;
    source.path_ = file;
    source.assets_ = std::make_shared<AssetCache>();
    nlohmann::json doc;
    if (isGltfPath(file)) {
        doc = nlohmann::json::parse(gltfSceneFor(file, file, options.gltf,
                                                 imageAfterOverrides(overrides),
                                                 source.assets_->store)
                                        .dump());
    } else {
        doc = parseJsonText(readTextFile(file, label, kMaxSceneFileBytes), label);
        if (!doc.is_object()) failExpected(label, "", "a JSON object", doc);
    }
    applyTechniqueOption(doc, options.technique);
    applyOverrides(doc, overrides);

    SceneContext& context = source.assets_->context;
    context.file = label;
    context.folder = file.parent_path();
    context.default_name = file.stem().string();
    context.max_image_size = options.max_image_size;
    context.assets = &source.assets_->store;

    Scene still;
    Animation animation;
    try {
        still = buildScene(doc, context);  // every value checked, every asset loaded
        animation = parseAnimation(doc, label);
    } catch (const UnknownKeyError& e) {
        blameOverride(e, overrides);
        throw;
    }
    source.animation_frames_ = animation.frames;
    for (AnimationTrack& track : animation.tracks)
        source.tracks_.push_back(std::make_shared<const Track>(Track{std::move(track)}));
    source.document_ = std::move(doc);
    if (source.tracks_.empty()) {
        source.assets_->still = std::make_shared<const Scene>(std::move(still));
        return source;
    }

    // Every key frame of every track, and one frame between consecutive keys, must give a valid
    // scene: a track that drives a value out of range fails here, not in the middle of a render.
    // Each block (camera, lights.N, objects.N, ...) checks on its own, so only the animated
    // blocks are checked, each once per distinct frame with its own tracks applied: the work is
    // linear in the tracks (checking the whole scene at every key frame was quadratic).
    std::map<std::vector<std::string>, std::vector<const AnimationTrack*>> parts;
    for (const auto& t : source.tracks_) parts[scenePartOf(t->track.parts)].push_back(&t->track);
    std::map<std::vector<std::string>, std::set<int>> checked;  // per block, frames done
    auto check = [&](const AnimationTrack& track, int frame) {
        const std::vector<std::string> part = scenePartOf(track.parts);
        if (!checked[part].insert(frame).second) return;
        if (part.empty()) {  // not in a block that checks alone: the whole scene
            (void)source.at(frame);
            return;
        }
        nlohmann::json value = *findAt(source.document_, part);
        for (const AnimationTrack* t : parts[part]) {
            const std::vector<std::string> rest(t->parts.begin() + static_cast<long>(part.size()),
                                                t->parts.end());
            if (nlohmann::json* target = findAt(value, rest)) *target = trackValueAt(*t, frame);
        }
        checkScenePart(value, part, context);
    };
    for (std::size_t t = 0; t < source.tracks_.size(); ++t) {
        const AnimationTrack& track = source.tracks_[t]->track;
        const std::vector<int>& frames = track.frames;
        const std::string where = "animation.tracks." + std::to_string(t);
        for (std::size_t k = 0; k < frames.size(); ++k) {
            try {
                check(track, frames[k]);
            } catch (const InputError& e) {
                failAt(label, where + ".keys." + std::to_string(k),
                       "at frame " + std::to_string(frames[k]) + ": " + withoutFile(e, label));
            }
            if (k + 1 == frames.size() || frames[k + 1] - frames[k] < 2) continue;
            const int middle = frames[k] + (frames[k + 1] - frames[k]) / 2;
            try {
                check(track, middle);
            } catch (const InputError& e) {
                failAt(label, where,
                       "between keys " + std::to_string(k) + " and " + std::to_string(k + 1) +
                           " (frame " + std::to_string(middle) + "): " + withoutFile(e, label));
            }
        }
    }
    return source;
}

Scene SceneSource::at(int frame) const {
    if (assets_->still) {
        Scene scene = *assets_->still;
        scene.frame = frame;
        return scene;
    }
    nlohmann::json doc = document_;
    for (const auto& track : tracks_) applyTrack(doc, track->track, frame);
    Scene scene = buildScene(doc, assets_->context);
    scene.frame = frame;
    return scene;
}

}  // namespace penumbra::scene
