// Rect lights for environment maps: see environment_lights.h.
#include "renderer/techniques/environment_lights.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "renderer/core/error.h"
#include "renderer/passes/environment_fold.h"
#include "renderer/scene/json_file.h"
#include "renderer/techniques/jitter_hash.h"

namespace penumbra::techniques {
namespace {

constexpr float kDegree = 3.14159265358979f / 180.0f;
constexpr int kSampleFaceSize = 64;               // cube faces the reference samples from
constexpr float kSampleExtent = 0.25f * kDegree;  // angular size of a sampled light

glm::vec3 rotateY(const glm::vec3& v, float degrees) {
    const float c = std::cos(degrees * kDegree), s = std::sin(degrees * kDegree);
    return {c * v.x + s * v.z, v.y, -s * v.x + c * v.z};
}

scene::CubeFaces facesOf(const scene::Scene& s, int size) {
    return scene::toCubeFaces(*s.environment->image, size, s.environment->intensity);
}

// The fit in FILE (relative to the scene's folder), its energy scaled by the environment's
// intensity like a fit of the map would be.
scene::LightFit readLightFit(const scene::Scene& s, const std::string& file) {
    std::filesystem::path path(file);
    if (path.is_relative()) path = s.path.parent_path() / path;
    const std::string label = "technique.env_lights_file: " + path.string();
    scene::LightFit fit = scene::lightFitFromJson(
        scene::parseJsonText(scene::readTextFile(path, label, std::size_t(64) << 20), label),
        label);
    for (auto& l : fit.lights) l.energy *= s.environment ? s.environment->intensity : 1.0f;
    return fit;
}

}  // namespace

scene::RectLight farLight(const scene::Scene& s, const scene::FittedLight& l) {
    const float rotation = s.environment ? s.environment->rotation_y : 0.0f;
    const glm::vec3 dir = rotateY(l.direction, rotation), up = rotateY(l.up, rotation);
    const float distance = 10.0f * s.camera.far;
    scene::RectLight light;
    light.position = dir * distance;
    light.target = glm::vec3(0.0f);
    light.up = up;
    light.size = {2.0f * distance * std::tan(0.5f * l.extent.x),
                  2.0f * distance * std::tan(0.5f * l.extent.y)};
    // The captured energy spread over the rect's own solid angle, 4 asin(sin(a) sin(b)) for
    // half-angles a and b (the face rectangle it came from is tilted, so its solid angle
    // differs): each light delivers the energy it took from the map.
    const double solid_angle =
        4.0 * std::asin(std::sin(0.5 * l.extent.x) * std::sin(0.5 * l.extent.y));
    light.color = l.energy / static_cast<float>(solid_angle);
    light.intensity = 1.0f;
    return light;
}

EnvironmentLights fittedEnvironmentLights(const Params& p, const scene::Scene& s) {
    scene::FitSettings settings;
    settings.threshold = p.get(kEnvThreshold);
    settings.max_lights = p.get(kEnvLights);
    settings.square = p.getEnum(kEnvShape) == EnvShape::Square;
    const int face_size = p.get(kEnvFaceSize);
    const std::string file = p.get(kEnvLightsFile);
    scene::LightFit fit;
    if (file.empty()) {
        fit = scene::fitLights(facesOf(s, face_size), settings);
    } else {
        fit = readLightFit(s, file);
        if (fit.lights.size() > static_cast<size_t>(settings.max_lights)) {
            for (size_t i = static_cast<size_t>(settings.max_lights); i < fit.lights.size(); ++i)
                fit.captured -= fit.lights[i].share;
            fit.lights.resize(static_cast<size_t>(settings.max_lights));
        }
    }
    EnvironmentLights out;
    for (const auto& l : fit.lights) out.lights.push_back(farLight(s, l));
    out.stats["lights_fitted"] = fit.lights.size();
    out.stats["energy_captured"] = fit.captured;
    return out;
}

EnvironmentLights sampledEnvironmentLights(const Params& p, const scene::Scene& s) {
    const int count = p.get(kEnvSamples);
    const scene::CubeFaces faces = facesOf(s, kSampleFaceSize);
    const int n = faces.size;
    std::vector<double> cdf;  // over face-major texels
    double total = 0;
    for (const auto& face : faces.energy)
        for (const auto& e : face) cdf.push_back(total += scene::luminance(e));
    EnvironmentLights out;
    out.fold = true;  // hundreds of lights: a batch of output layers, not one each
    out.stats["env_samples"] = count;
    if (!(total > 0)) return out;
    const std::uint32_t seed = static_cast<std::uint32_t>(p.get(kSeed));
    for (int k = 0; k < count; ++k) {
        // Stratified in the cumulative energy: sample k lies in [k, k + 1) / count of it.
        const double target =
            (k + hashToUnit(seed, std::uint32_t(k), 0u)) / static_cast<double>(count) * total;
        const size_t t = static_cast<size_t>(
            std::min<std::ptrdiff_t>(std::lower_bound(cdf.begin(), cdf.end(), target) - cdf.begin(),
                                     static_cast<std::ptrdiff_t>(cdf.size()) - 1));
        const int face = static_cast<int>(t / size_t(n * n));
        const int texel = static_cast<int>(t % size_t(n * n));
        const glm::vec3 e = faces.energy[size_t(face)][size_t(texel)];
        // A direction jittered inside the texel.
        const float a =
            -1.0f + 2.0f * (float(texel % n) + hashToUnit(seed, std::uint32_t(k), 1u)) / n;
        const float b =
            -1.0f + 2.0f * (float(texel / n) + hashToUnit(seed, std::uint32_t(k), 2u)) / n;
        scene::FittedLight l;
        l.direction = glm::normalize(scene::cubeDirection(face, a, b));
        const glm::vec3 helper =
            std::fabs(l.direction.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
        l.up = glm::normalize(helper - glm::dot(helper, l.direction) * l.direction);
        l.extent = {kSampleExtent, kSampleExtent};
        // An equal share of the luminance energy, in the texel's colour.
        l.energy = e * static_cast<float>(total / count / scene::luminance(e));
        out.lights.push_back(farLight(s, l));
    }
    return out;
}

int fittedEnvironmentLightsMax(const Params& p) {
    return p.get(kEnvLights);
}

int sampledEnvironmentLightsMax(const Params& p) {
    // Folded: a batch of lights, the irradiance layer, and the fold's sum (one more).
    return std::min(p.get(kEnvSamples), passes::EnvironmentFold::kBatch) + 2;
}

}  // namespace penumbra::techniques
