// The scene document's top level and its image, environment and technique blocks, each value
// checked for type, range and consistency; the camera (camera_json.cpp), lights
// (light_json.cpp) and objects (object_json.cpp) have their own files.
#include "renderer/scene/scene_json.h"

#include <algorithm>
#include <climits>
#include <cmath>

#include "renderer/core/error.h"
#include "renderer/core/json_bounds.h"
#include "renderer/scene/gltf_scene.h"

namespace penumbra::scene {
namespace {

ImageSettings readImage(const Field& f, int max_size) {
    ImageSettings image;
    if (!f.present()) return image;
    f.expectObject({"width", "height", "samples"});
    const Field width = f.member("width");
    const Field height = f.member("height");
    const Field samples = f.member("samples");
    if (width.present()) image.width = static_cast<int>(width.integer(1, max_size));
    if (height.present()) image.height = static_cast<int>(height.integer(1, max_size));
    if (samples.present()) {
        image.samples = static_cast<int>(samples.integer(1, 8));
        if (image.samples != 1 && image.samples != 2 && image.samples != 4 && image.samples != 8)
            samples.expected("1, 2, 4 or 8");
    }
    return image;
}

std::optional<Environment> readEnvironment(const Field& f, const SceneContext& context) {
    if (!f.present()) return std::nullopt;
    f.expectObject({"image", "intensity", "rotation_y"});
    Environment env;
    const Field image = f.member("image");
    if (!image.present()) image.fail("missing (the path of an .exr or .hdr file)");
    const std::string path = image.string();
    if (path.empty()) image.fail("empty path");
    env.path = resolveAsset(context, path);
    try {
        env.image = context.assets->environment(env.path);
    } catch (const InputError& e) {
        image.fail(e.what());
    }
    const Field intensity = f.member("intensity");
    env.intensity = static_cast<float>(intensity.numberOr(env.intensity));
    if (env.intensity < 0.0f) intensity.expected("a number >= 0");
    env.rotation_y = static_cast<float>(f.member("rotation_y").numberOr(env.rotation_y));
    return env;
}

nlohmann::json readTechnique(const Field& f) {
    if (!f.present()) return nlohmann::json{{"name", "hard"}};
    f.expectObject();
    const Field name = f.member("name");
    if (!name.present()) name.fail("missing (the technique to render with)");
    if (name.string().empty()) name.fail("empty technique name");
    return f.json();  // the parameters are the technique registry's to check
}

}  // namespace

std::filesystem::path resolveAsset(const SceneContext& context, const std::string& path) {
    const std::filesystem::path p(path);
    return p.is_absolute() ? p : context.folder / p;
}

std::vector<std::string> scenePartOf(const std::vector<std::string>& parts) {
    if (parts.empty()) return {};
    const std::string& top = parts[0];
    if (top == "lights" || top == "objects")
        return parts.size() >= 2 ? std::vector<std::string>{top, parts[1]}
                                 : std::vector<std::string>{};
    if (top == "camera" || top == "image" || top == "environment" || top == "technique")
        return {top};
    return {};
}

void checkScenePart(const nlohmann::json& value, const std::vector<std::string>& part,
                    const SceneContext& context) {
    std::string key;
    for (const std::string& p : part) key = joinKey(key, p);
    const Field f(&value, key, context.file);
    const std::string& top = part.at(0);
    if (top == "camera") {
        bool far_auto = false;
        (void)readCamera(f, context, far_auto);
    } else if (top == "image") {
        (void)readImage(f, context.max_image_size);
    } else if (top == "environment") {
        (void)readEnvironment(f, context);
    } else if (top == "technique") {
        (void)readTechnique(f);
    } else if (top == "lights") {
        (void)readLight(f, context);
    } else if (top == "objects") {
        (void)buildObject(f, static_cast<std::size_t>(std::stoul(part.at(1))), context);
    }
}

Scene buildScene(const nlohmann::json& doc, const SceneContext& context) {
    const Field root(&doc, "", context.file);
    root.expectObject({"format", "name", "camera", "image", "lights", "environment", "objects",
                       "technique", "animation"});
    const Field format = root.member("format");
    if (!format.present()) format.fail(std::string("missing (expected \"") + kSceneFormat + "\")");
    if (format.string() != kSceneFormat)
        format.fail("unsupported format '" + quoteText(format.string()) + "' (expected \"" +
                    kSceneFormat + "\")");

    Scene scene;
    scene.path = context.file;
    scene.name = context.default_name;
    if (const Field name = root.member("name"); name.present()) {
        scene.name = name.string();
        if (scene.name.empty()) name.fail("empty name");
        // The default output is out/<name>.####.exr: a path would write outside out/.
        if (scene.name == "." || scene.name == ".." ||
            scene.name.find_first_of(std::string("/\0", 2)) != std::string::npos ||
            scene.name.size() > 200)
            name.fail("'" + quoteText(scene.name) +
                      "' is not a plain file name (no '/', not '.' or '..', at most 200 bytes)");
    }
    bool far_auto = false;
    scene.camera = readCamera(root.member("camera"), context, far_auto);
    scene.image = readImage(root.member("image"), context.max_image_size);
    scene.lights = readLights(root.member("lights"), context);
    scene.environment = readEnvironment(root.member("environment"), context);
    if (scene.lights.empty() && !scene.environment)
        root.member("lights").fail("the scene has no light and no environment (nothing lights it)");
    scene.objects = buildObjects(root.member("objects"), context);
    if (far_auto) {  // a glTF camera's infinite zfar: far enough for every object
        scene.camera.far = std::max(coveringFar(scene.camera.position, objectBounds(scene.objects)),
                                    2.0f * scene.camera.near);
        if (!std::isfinite(scene.camera.far))
            root.member("camera").fail("no finite far plane covers the objects");
    }
    scene.technique = readTechnique(root.member("technique"));
    return scene;
}

}  // namespace penumbra::scene
