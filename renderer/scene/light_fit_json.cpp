// The fit-lights file ({"schema": "penumbra-lights", ...}): written from a LightFit, and read
// back with every value typed, finite and in range (see light_fitting.h).
#include <cmath>

#include "renderer/core/json_field.h"
#include "renderer/scene/light_fitting.h"

namespace penumbra::scene {

nlohmann::json lightFitJson(const LightFit& fit, const FitSettings& s, int face_size) {
    constexpr double kDeg = 180.0 / 3.14159265358979323846;
    auto vec = [](const glm::vec3& v) { return nlohmann::json::array({v.x, v.y, v.z}); };
    nlohmann::json lights = nlohmann::json::array();
    for (const auto& l : fit.lights)
        lights.push_back({{"face", kCubeFaceNames[size_t(l.face)]},
                          {"texels", {l.x0, l.y0, l.x1, l.y1}},
                          {"direction", vec(l.direction)},
                          {"right", vec(l.right)},
                          {"up", vec(l.up)},
                          {"extent_deg", {l.extent.x * kDeg, l.extent.y * kDeg}},
                          {"solid_angle", l.solid_angle},
                          {"radiance", vec(l.radiance())},
                          {"energy_share", l.share}});
    return {{"schema", "penumbra-lights"},
            {"schema_version", 1},
            {"face_size", face_size},
            {"threshold", s.threshold},
            {"max_lights", s.max_lights},
            {"shape", s.square ? "square" : "rect"},
            {"residual", s.residual},
            {"total_energy", fit.total},
            {"captured_share", fit.captured},
            {"residual_share", 1.0 - fit.captured},
            {"lights", lights}};
}

namespace {

constexpr double kMaxRadiance = 1e10;  // far above any sky or sun a map holds
constexpr double kFullSphere = 4.0 * 3.14159265358979;

const Field& needed(const Field& f) {
    if (!f.present()) f.fail("missing");
    return f;
}

glm::vec3 unitVector(const Field& f) {
    const glm::vec3 v = f.vec3();
    if (!(glm::length(v) > 0.5f && glm::length(v) < 2.0f)) f.expected("a unit vector");
    return v;
}

// One element of "lights", every value typed, finite and in range.
FittedLight readFittedLight(const Field& l) {
    if (!l.json().is_object()) l.expected("an object");
    FittedLight f;
    f.direction = glm::normalize(unitVector(needed(l.member("direction"))));
    f.right = needed(l.member("right")).vec3();
    f.up = needed(l.member("up")).vec3();
    const Field radiance_field = needed(l.member("radiance"));
    const glm::vec3 radiance = radiance_field.vec3();
    for (int c = 0; c < 3; ++c)
        if (!(radiance[c] >= 0.0f && radiance[c] <= kMaxRadiance))
            radiance_field.expected("3 values in [0, 1e10]");
    const Field extent = needed(l.member("extent_deg"));
    const glm::vec2 e = extent.vec2();
    if (!(e.x > 0 && e.x < 180) || !(e.y > 0 && e.y < 180)) extent.expected("2 angles in (0, 180)");
    constexpr float kRad = 3.14159265358979f / 180.0f;
    f.extent = {e.x * kRad, e.y * kRad};
    const Field solid_angle = needed(l.member("solid_angle"));
    f.solid_angle = solid_angle.number();
    if (!(f.solid_angle > 0 && f.solid_angle <= kFullSphere))
        solid_angle.expected("a number in (0, 4 pi]");
    f.energy = radiance * static_cast<float>(f.solid_angle);
    if (const Field share = l.member("energy_share"); share.present()) f.share = share.number(0, 1);
    return f;
}

}  // namespace

LightFit lightFitFromJson(const nlohmann::json& j, const std::string& where) {
    // Every value typed, finite and in range, each error naming its key (Field's messages).
    const Field root(&j, "", where);
    if (!j.is_object() || j.value("schema", nlohmann::json()) != "penumbra-lights")
        root.member("schema").fail(
            "expected \"penumbra-lights\" (a file written by penumbra fit-lights)");
    LightFit fit;
    if (const Field total = root.member("total_energy"); total.present())
        fit.total = total.number(0, 1e30);
    if (const Field captured = root.member("captured_share"); captured.present())
        fit.captured = captured.number(0, 1);
    const Field lights = needed(root.member("lights"));
    const std::size_t count = lights.arraySize();
    for (std::size_t i = 0; i < count; ++i)
        fit.lights.push_back(readFittedLight(lights.element(i)));
    return fit;
}

}  // namespace penumbra::scene
