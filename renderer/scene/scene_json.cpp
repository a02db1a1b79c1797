// The scene document's top level and its camera, image, lights, environment and technique
// blocks, each value checked for type, range and consistency.
#include "renderer/scene/scene_json.h"

#include <cmath>

#include "renderer/core/error.h"
#include "renderer/core/json_bounds.h"

namespace penumbra::scene {
namespace {

bool parallel(const glm::vec3& a, const glm::vec3& b) {
    return glm::length(glm::cross(glm::normalize(a), glm::normalize(b))) < 1e-6f;
}

Camera readCamera(const Field& f) {
    Camera c;
    if (!f.present()) return c;
    f.expectObject({"position", "target", "up", "fov_y", "near", "far"});
    c.position = f.member("position").vec3Or(c.position);
    c.target = f.member("target").vec3Or(c.target);
    c.up = f.member("up").vec3Or(c.up);
    const Field fov = f.member("fov_y");
    c.fov_y = static_cast<float>(fov.numberOr(c.fov_y));
    if (!(c.fov_y > 0.0f && c.fov_y < 180.0f)) fov.fail("must be in (0, 180) degrees");
    const Field near = f.member("near");
    c.near = static_cast<float>(near.numberOr(c.near));
    if (!(c.near > 0.0f)) near.fail("must be > 0");
    const Field far = f.member("far");
    c.far = static_cast<float>(far.numberOr(c.far));
    if (!(c.far > c.near)) far.fail("must be greater than camera.near");
    const glm::vec3 view = c.target - c.position;
    if (glm::length(view) == 0.0f)
        f.member("target").fail("same as camera.position (no view direction)");
    if (glm::length(c.up) == 0.0f) f.member("up").fail("zero vector");
    if (parallel(view, c.up)) f.member("up").fail("parallel to the view direction");
    return c;
}

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
            samples.fail("must be 1, 2, 4 or 8");
    }
    return image;
}

RectLight readLight(const Field& f) {
    RectLight light;
    f.expectObject({"type", "position", "target", "up", "size", "color", "intensity"});
    if (const Field type = f.member("type"); type.present() && type.string() != "rect")
        type.fail("unsupported light type '" + type.string() + "' (supported: rect)");
    light.position = f.member("position").vec3Or(light.position);
    light.target = f.member("target").vec3Or(light.target);
    light.up = f.member("up").vec3Or(light.up);
    if (const Field size = f.member("size"); size.present()) {
        light.size = size.vec2();
        if (!(light.size.x > 0.0f && light.size.y > 0.0f))
            size.fail("zero-size light (width and height must be > 0)");
    }
    if (const Field color = f.member("color"); color.present()) {
        light.color = color.vec3();
        if (light.color.r < 0.0f || light.color.g < 0.0f || light.color.b < 0.0f)
            color.fail("must be >= 0");
    }
    if (const Field intensity = f.member("intensity"); intensity.present()) {
        light.intensity = static_cast<float>(intensity.number());
        if (light.intensity < 0.0f) intensity.fail("must be >= 0");
    }
    const glm::vec3 facing = light.target - light.position;
    if (glm::length(facing) == 0.0f)
        f.member("target").fail("same as position (the light faces nowhere)");
    if (glm::length(light.up) == 0.0f) f.member("up").fail("zero vector");
    if (parallel(facing, light.up))
        f.member("up").fail("parallel to the direction the light faces");
    return light;
}

std::vector<RectLight> readLights(const Field& f) {
    std::vector<RectLight> lights;
    if (!f.present()) return lights;
    const std::size_t count = f.arraySize();
    for (std::size_t i = 0; i < count; ++i) lights.push_back(readLight(f.element(i)));
    return lights;
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
    if (env.intensity < 0.0f) intensity.fail("must be >= 0");
    env.rotation_y = static_cast<float>(f.member("rotation_y").numberOr(env.rotation_y));
    return env;
}

nlohmann::json readTechnique(const Field& f) {
    if (!f.present()) return nlohmann::json{{"name", "hard"}};
    if (!f.json().is_object()) f.fail("expected an object, got " + describeType(f.json()));
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
        (void)readCamera(f);
    } else if (top == "image") {
        (void)readImage(f, context.max_image_size);
    } else if (top == "environment") {
        (void)readEnvironment(f, context);
    } else if (top == "technique") {
        (void)readTechnique(f);
    } else if (top == "lights") {
        (void)readLight(f);
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
    scene.camera = readCamera(root.member("camera"));
    scene.image = readImage(root.member("image"), context.max_image_size);
    scene.lights = readLights(root.member("lights"));
    scene.environment = readEnvironment(root.member("environment"), context);
    if (scene.lights.empty() && !scene.environment)
        root.member("lights").fail("the scene has no light and no environment (nothing lights it)");
    scene.objects = buildObjects(root.member("objects"), context);
    scene.technique = readTechnique(root.member("technique"));
    return scene;
}

}  // namespace penumbra::scene
