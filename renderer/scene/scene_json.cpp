// The scene document's top level and its camera, image, lights, environment and technique
// blocks, each value checked for type, range and consistency; a camera or a light entry may
// take a glTF's camera or punctual lights instead ({"gltf": ...}, gltf_scene.h).
#include "renderer/scene/scene_json.h"

#include <algorithm>
#include <climits>
#include <cmath>

#include "renderer/core/error.h"
#include "renderer/core/json_bounds.h"
#include "renderer/scene/gltf_scene.h"

namespace penumbra::scene {
namespace {

bool parallel(const glm::vec3& a, const glm::vec3& b) {
    return glm::length(glm::cross(glm::normalize(a), glm::normalize(b))) < 1e-6f;
}

// The checks every camera passes, explicit or taken from a glTF.
void checkCamera(const Camera& c, const Field& f) {
    if (!(c.fov_y > 0.0f && c.fov_y < 180.0f))
        f.member("fov_y").fail("must be in (0, 180) degrees");
    if (!(c.near > 0.0f)) f.member("near").fail("must be > 0");
    if (!(c.far > c.near)) f.member("far").fail("must be greater than camera.near");
    const glm::vec3 view = c.target - c.position;
    if (glm::length(view) == 0.0f)
        f.member("target").fail("same as camera.position (no view direction)");
    if (glm::length(c.up) == 0.0f) f.member("up").fail("zero vector");
    if (parallel(view, c.up)) f.member("up").fail("parallel to the view direction");
}

// The placement of the camera a {"gltf": ...} camera names by "index" or "name", else the first.
const GltfPlacement& chosenGltfCamera(const Field& f, const GltfFile& file) {
    const Field index = f.member("index");
    const Field name = f.member("name");
    if (index.present() && name.present()) f.fail("has both 'index' and 'name' (give one)");
    const std::string count = std::to_string(file.cameras.size());
    int wanted = -1;
    if (index.present()) {
        wanted = static_cast<int>(index.integer(0, INT_MAX));
        if (static_cast<std::size_t>(wanted) >= file.cameras.size())
            index.fail("camera " + std::to_string(wanted) + " does not exist (" + file.label +
                       " has " + count + " cameras)");
    } else if (name.present()) {
        const std::string wanted_name = name.string();
        for (std::size_t i = 0; i < file.cameras.size() && wanted < 0; ++i)
            if (file.cameras[i].name == wanted_name) wanted = static_cast<int>(i);
        if (wanted < 0)
            name.fail("no camera named '" + quoteText(wanted_name) + "' in " + file.label);
    }
    if (wanted < 0) {
        if (const GltfPlacement* first = firstPlacedCamera(file)) return *first;
        f.member("gltf").fail(file.label + " has no camera placed in its glTF scene");
    }
    for (const GltfPlacement& p : file.placed_cameras)
        if (p.index == wanted) return p;
    (index.present() ? index : name)
        .fail("camera " + std::to_string(wanted) + " of " + file.label +
              " is placed by no node of its glTF scene");
}

// {"gltf": FILE, "index" or "name"}: that glTF camera; FAR_AUTO when its zfar is infinite.
Camera readGltfCamera(const Field& f, const SceneContext& context, bool& far_auto) {
    f.expectObject({"gltf", "index", "name"});
    const Field path = f.member("gltf");
    const auto file = readGltfReference(path, context);
    const GltfPlacement& placed = chosenGltfCamera(f, *file);
    Camera c;
    try {
        c = cameraFromGltf(*file, placed, checkedBounds(*file));
    } catch (const InputError& e) {
        path.fail(e.what());
    }
    far_auto = !file->cameras[static_cast<std::size_t>(placed.index)].zfar;
    return c;
}

Camera readCamera(const Field& f, const SceneContext& context, bool& far_auto) {
    Camera c;
    far_auto = false;
    if (!f.present()) return c;
    if (f.json().is_object() && f.json().contains("gltf")) {
        c = readGltfCamera(f, context, far_auto);
        checkCamera(c, f);
        return c;
    }
    f.expectObject({"position", "target", "up", "fov_y", "near", "far"});
    c.position = f.member("position").vec3Or(c.position);
    c.target = f.member("target").vec3Or(c.target);
    c.up = f.member("up").vec3Or(c.up);
    c.fov_y = static_cast<float>(f.member("fov_y").numberOr(c.fov_y));
    c.near = static_cast<float>(f.member("near").numberOr(c.near));
    c.far = static_cast<float>(f.member("far").numberOr(c.far));
    checkCamera(c, f);
    return c;
}

// The world bounds of OBJECTS' vertices (for a glTF camera with an infinite zfar).
Bounds objectBounds(const std::vector<Object>& objects) {
    Bounds b{glm::vec3(INFINITY), glm::vec3(-INFINITY)};
    for (const Object& o : objects)
        for (const Mesh& mesh : o.model->meshes)
            for (const glm::vec3& p : mesh.positions) {
                const glm::vec3 w(o.transform * glm::vec4(p, 1.0f));
                b.min = glm::min(b.min, w);
                b.max = glm::max(b.max, w);
            }
    return b;
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

// The checks every light passes, explicit or taken from a glTF.
void checkLight(const RectLight& light, const Field& f) {
    const glm::vec3 facing = light.target - light.position;
    if (glm::length(facing) == 0.0f)
        f.member("target").fail("same as position (the light faces nowhere)");
    if (glm::length(light.up) == 0.0f) f.member("up").fail("zero vector");
    if (parallel(facing, light.up))
        f.member("up").fail("parallel to the direction the light faces");
}

glm::vec2 readLightSize(const Field& size) {
    const glm::vec2 s = size.vec2();
    if (!(s.x > 0.0f && s.y > 0.0f)) size.fail("zero-size light (width and height must be > 0)");
    return s;
}

RectLight readRectLight(const Field& f) {
    RectLight light;
    f.expectObject({"type", "position", "target", "up", "size", "color", "intensity"});
    if (const Field type = f.member("type"); type.present() && type.string() != "rect")
        type.fail("unsupported light type '" + type.string() + "' (supported: rect)");
    light.position = f.member("position").vec3Or(light.position);
    light.target = f.member("target").vec3Or(light.target);
    light.up = f.member("up").vec3Or(light.up);
    if (const Field size = f.member("size"); size.present()) light.size = readLightSize(size);
    if (const Field color = f.member("color"); color.present()) {
        light.color = color.vec3();
        if (light.color.r < 0.0f || light.color.g < 0.0f || light.color.b < 0.0f)
            color.fail("must be >= 0");
    }
    if (const Field intensity = f.member("intensity"); intensity.present()) {
        light.intensity = static_cast<float>(intensity.number());
        if (light.intensity < 0.0f) intensity.fail("must be >= 0");
    }
    checkLight(light, f);
    return light;
}

// {"gltf": FILE, "size": [w, h]}: every punctual light FILE's glTF scene places.
std::vector<RectLight> readGltfLights(const Field& f, const SceneContext& context) {
    f.expectObject({"gltf", "size"});
    const Field path = f.member("gltf");
    const auto file = readGltfReference(path, context);
    std::optional<glm::vec2> size;
    if (const Field s = f.member("size"); s.present()) size = readLightSize(s);
    std::vector<RectLight> lights;
    try {
        lights = lightsFromGltf(*file, size);
    } catch (const InputError& e) {
        path.fail(e.what());
    }
    if (lights.empty())
        path.fail(file->label + " has no KHR_lights_punctual light placed in its glTF scene");
    for (const RectLight& light : lights) checkLight(light, f);
    return lights;
}

// One element of "lights": a rect light, or a glTF's lights.
std::vector<RectLight> readLight(const Field& f, const SceneContext& context) {
    if (f.json().is_object() && f.json().contains("gltf")) return readGltfLights(f, context);
    return {readRectLight(f)};
}

std::vector<RectLight> readLights(const Field& f, const SceneContext& context) {
    std::vector<RectLight> lights;
    if (!f.present()) return lights;
    const std::size_t count = f.arraySize();
    for (std::size_t i = 0; i < count; ++i)
        for (const RectLight& light : readLight(f.element(i), context)) lights.push_back(light);
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
