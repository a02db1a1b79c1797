// The scene's "lights" array: rect lights, or a glTF's punctual lights as rect lights of a given
// size ({"gltf": ..., "size": [w, h]}); every light checked alike (see scene_json.h).
#include <climits>

#include "renderer/core/error.h"
#include "renderer/core/json_bounds.h"
#include "renderer/scene/gltf_scene.h"
#include "renderer/scene/scene_json.h"

namespace penumbra::scene {
namespace {

// The checks every light passes, explicit or taken from a glTF.
void checkLight(const RectLight& light, const Field& f) {
    const glm::vec3 facing = light.target - light.position;
    if (glm::length(facing) == 0.0f)
        f.member("target").fail("same as position (the light faces nowhere)");
    if (glm::length(light.up) == 0.0f) f.member("up").fail("zero vector");
    if (parallelDirections(facing, light.up))
        f.member("up").fail("parallel to the direction the light faces");
}

glm::vec2 readLightSize(const Field& size) {
    const glm::vec2 s = size.vec2();
    if (!(s.x > 0.0f && s.y > 0.0f)) size.expected("a width and height > 0");
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
            color.expected("three numbers >= 0");
    }
    if (const Field intensity = f.member("intensity"); intensity.present()) {
        light.intensity = static_cast<float>(intensity.number());
        if (light.intensity < 0.0f) intensity.expected("a number >= 0");
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
}  // namespace

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

}  // namespace penumbra::scene
