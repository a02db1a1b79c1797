// glTF cameras and punctual lights as Penumbra's Camera and RectLight, the framing camera and
// the default light. Light mapping: a Lambertian rect of area A and radiance L has intensity
// L * A along its normal, so a glTF intensity I (candela) becomes L = I / A (the same on-axis
// irradiance far away); a directional light's illuminance E (lux) at distance D: L = E D^2 / A.
#include "renderer/scene/gltf_scene.h"

#include <algorithm>
#include <cmath>

#include "renderer/core/error.h"
#include "renderer/core/json_field.h"

namespace penumbra::scene {
namespace {

std::string lightKey(int index) {
    return "extensions.KHR_lights_punctual.lights." + std::to_string(index);
}

bool finite(const glm::dvec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// The unit direction M * LOCAL, or nullopt when it vanishes or overflows.
std::optional<glm::dvec3> direction(const glm::dmat4& m, const glm::dvec3& local) {
    const glm::dvec3 d = glm::dmat3(m) * local;
    const double length = glm::length(d);
    if (!(length > 0.0) || !std::isfinite(length)) return std::nullopt;
    return d / length;
}

// PREFERRED when usable as the up axis of something facing FACING, else world +Y, else -Z.
glm::dvec3 upFor(const glm::dvec3& facing, const std::optional<glm::dvec3>& preferred) {
    for (const glm::dvec3& up : {preferred.value_or(glm::dvec3(0.0)), glm::dvec3(0, 1, 0)})
        if (glm::length(up) > 0.0 && glm::length(glm::cross(up, facing)) > 1e-3) return up;
    return {0, 0, -1};
}

// A float value of V (finite in float), else fails at KEY with WHAT.
float toFloat(double v, const GltfFile& file, const std::string& key, const char* what) {
    const auto f = static_cast<float>(v);
    if (!std::isfinite(f)) failAt(file.label, key, what);
    return f;
}

}  // namespace

float coveringFar(const glm::vec3& from, const Bounds& box) {
    float far = 0.0f;
    for (int i = 0; i < 8; ++i) {
        const glm::vec3 corner((i & 1) ? box.max.x : box.min.x, (i & 2) ? box.max.y : box.min.y,
                               (i & 4) ? box.max.z : box.min.z);
        far = std::max(far, glm::length(corner - from));
    }
    return far * kFarMargin;
}

Bounds checkedBounds(const GltfFile& file) {
    const Bounds& b = file.bounds;
    if (!finite(glm::dvec3(b.min)) || !finite(glm::dvec3(b.max)) || !std::isfinite(b.radius()))
        failAt(file.label, "", "the model's bounds are not finite (a vertex is NaN or too far)");
    if (!(b.radius() > 0.0f))
        failAt(file.label, "", "the model has no extent (every vertex at one point)");
    return b;
}

const GltfPlacement* firstPlacedCamera(const GltfFile& file) {
    const GltfPlacement* first = nullptr;
    for (const GltfPlacement& p : file.placed_cameras)
        if (!first || p.index < first->index) first = &p;
    return first;
}

Camera cameraFromGltf(const GltfFile& file, const GltfPlacement& placed, const Bounds& cover) {
    const GltfCamera& c = file.cameras.at(static_cast<std::size_t>(placed.index));
    const std::string key = "cameras." + std::to_string(placed.index);
    if (!c.perspective)
        failAt(file.label, key,
               "an orthographic camera: penumbra renders perspective views only (remove the "
               "node's camera to get a framing camera, or give the scene a camera of its own)");
    const std::string node = "nodes." + std::to_string(placed.node);
    const glm::dvec3 position(placed.world[3]);
    const auto forward = direction(placed.world, {0, 0, -1});
    if (!finite(position) || !forward)
        failAt(file.label, node, "the camera's transform gives no position or view direction");
    Camera camera;
    camera.position = glm::vec3(position);
    double distance = glm::length(glm::dvec3(cover.center()) - position);
    if (!(distance > 0.0) || !std::isfinite(distance)) distance = 1.0;
    camera.target = glm::vec3(position + *forward * distance);
    camera.up = glm::vec3(upFor(*forward, direction(placed.world, {0, 1, 0})));
    camera.fov_y = static_cast<float>(glm::degrees(c.yfov));
    camera.near = static_cast<float>(c.znear);
    if (!(camera.near > 0.0f) || !std::isfinite(camera.near))
        failAt(file.label, key + ".perspective.znear", "not a positive float");
    const double far = c.zfar ? *c.zfar : coveringFar(camera.position, cover);
    camera.far = toFloat(std::max(far, 2.0 * camera.near), file, key + ".perspective.zfar",
                         "beyond float range");
    return camera;
}

Camera framingCamera(const Bounds& model, float aspect, const Bounds& cover) {
    const float half_y = glm::radians(kFramingFovY) * 0.5f;
    const float half_x = std::atan(std::tan(half_y) * aspect);
    const float radius = model.radius() * kFramingMargin;
    const float distance = radius / std::sin(std::min(half_y, half_x));
    const float azimuth = glm::radians(kFramingAzimuth);
    const float elevation = glm::radians(kFramingElevation);
    const glm::vec3 toward(std::sin(azimuth) * std::cos(elevation), std::sin(elevation),
                           std::cos(azimuth) * std::cos(elevation));
    Camera camera;
    camera.target = model.center();
    camera.position = model.center() + toward * distance;
    camera.up = {0, 1, 0};
    camera.fov_y = kFramingFovY;
    camera.near = 0.5f * (distance - radius);
    camera.far = std::max(coveringFar(camera.position, cover), 2.0f * camera.near);
    return camera;
}

std::vector<RectLight> lightsFromGltf(const GltfFile& file, std::optional<glm::vec2> size) {
    if (file.placed_lights.size() > kMaxGltfLights)
        failAt(file.label, "extensions.KHR_lights_punctual",
               "the glTF scene places " + std::to_string(file.placed_lights.size()) +
                   " lights, more than " + std::to_string(kMaxGltfLights));
    const Bounds bounds = checkedBounds(file);
    const glm::dvec3 center(bounds.center());
    const glm::vec2 s = size.value_or(glm::vec2(kPunctualLightSide * bounds.radius()));
    const double area = double{s.x} * double{s.y};
    std::vector<RectLight> lights;
    for (const GltfPlacement& placed : file.placed_lights) {
        const GltfPunctualLight& l = file.lights.at(static_cast<std::size_t>(placed.index));
        const std::string key = lightKey(placed.index);
        glm::dvec3 position(placed.world[3]);
        const auto along = direction(placed.world, {0, 0, -1});  // where spot/directional point
        if (!finite(position) || !along)
            failAt(file.label, "nodes." + std::to_string(placed.node),
                   "the light's transform gives no position or direction");
        glm::dvec3 facing = *along;
        double intensity = l.intensity / area;  // candela -> radiance of a rect of area A
        if (l.type == "point") {
            const glm::dvec3 to_center = center - position;
            facing =
                glm::length(to_center) > 0.0 ? glm::normalize(to_center) : glm::dvec3(0, -1, 0);
        } else if (l.type == "directional") {
            const double distance = double{kDirectionalDistance} * bounds.radius();
            position = center - facing * distance;
            intensity = l.intensity * distance * distance / area;  // lux -> radiance
        }
        RectLight light;
        light.position = glm::vec3(position);
        light.target = glm::vec3(position + facing * std::max(1.0, glm::length(center - position)));
        const auto node_up = l.type == "point" ? std::nullopt : direction(placed.world, {0, 1, 0});
        light.up = glm::vec3(upFor(facing, node_up));
        light.size = s;
        light.color = glm::vec3(l.color);
        light.intensity = toFloat(intensity, file, key + ".intensity",
                                  "gives a rect light intensity beyond float range");
        lights.push_back(light);
    }
    return lights;
}

RectLight defaultLight(const Bounds& model, std::optional<glm::vec2> size) {
    const float distance = kDefaultLightDistance * model.radius();
    RectLight light;
    light.target = model.center();
    light.position = model.center() + glm::normalize(glm::vec3(-1, 3, 1)) * distance;
    light.up = {0, 0, -1};
    light.size = size.value_or(glm::vec2(model.radius()));
    light.intensity = kDefaultLightIrradiance * distance * distance / (light.size.x * light.size.y);
    return light;
}

}  // namespace penumbra::scene
