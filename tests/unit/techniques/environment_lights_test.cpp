// Environment lights: a fitted or sampled light, placed far away as a rect light, delivers the
// energy it took from the map (its exact irradiance at the origin, facing it, is the energy's
// luminance), turned by rotation_y; the sampled lights share the map's energy equally.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>

#include "renderer/core/error.h"
#include "renderer/core/light_geometry.h"
#include "renderer/techniques/environment_lights.h"

using namespace penumbra;

namespace {

// Irradiance at the origin from LIGHT for a receiver facing it, of radiance luminance.
double irradiance(const scene::RectLight& light) {
    const auto c = light.corners();
    const std::array<glm::dvec3, 4> corners = {glm::dvec3(c[0]), glm::dvec3(c[1]), glm::dvec3(c[2]),
                                               glm::dvec3(c[3])};
    return rectLightIrradiance(corners, glm::dvec3(light.forward()), glm::dvec3(0.0),
                               -glm::dvec3(light.forward())) *
           scene::luminance(light.radiance());
}

scene::Scene skyScene(float rotation) {
    scene::Scene s;
    auto image = std::make_shared<scene::EnvironmentImage>();
    image->width = 64, image->height = 32;
    image->rgb.assign(64 * 32 * 3, 0.0f);
    for (int x = 40; x < 44; ++x)
        for (int y = 8; y < 11; ++y)
            for (int c = 0; c < 3; ++c) image->rgb[size_t((y * 64 + x) * 3 + c)] = 50.0f;
    s.environment = scene::Environment{"sky.exr", 1.0f, rotation, image};
    return s;
}

}  // namespace

TEST(EnvironmentLights, FarLightDeliversItsEnergy) {
    scene::FittedLight l;
    l.direction = glm::normalize(glm::vec3(0.3f, 0.8f, -0.2f));
    l.up = glm::normalize(glm::cross(l.direction, glm::vec3(1, 0, 0)));
    l.extent = {0.2f, 0.1f};
    l.energy = glm::vec3(0.5f, 0.4f, 0.3f);
    const scene::RectLight light = techniques::farLight(scene::Scene{}, l);
    EXPECT_NEAR(glm::dot(glm::normalize(light.position), l.direction), 1.0f, 1e-6f);
    // A small light facing the receiver: irradiance = radiance x projected solid angle, the
    // energy less a second-order term in the half-angles (0.2% for these 0.1 and 0.05 rad).
    EXPECT_NEAR(irradiance(light), scene::luminance(l.energy), 5e-3 * scene::luminance(l.energy));
}

TEST(EnvironmentLights, RotationTurnsTheMapAboutY) {
    scene::FittedLight l;
    l.direction = {0, 0, -1};
    l.up = {0, 1, 0};
    l.extent = {0.1f, 0.1f};
    l.energy = glm::vec3(1.0f);
    const auto turned = techniques::farLight(skyScene(90.0f), l);
    EXPECT_NEAR(glm::distance(glm::normalize(turned.position), glm::vec3(-1, 0, 0)), 0.0f, 1e-5f);
}

TEST(EnvironmentLights, FittedAndSampledLightsCarryTheMapsEnergy) {
    const scene::Scene s = skyScene(0.0f);
    nlohmann::json block = {{"name", "css"}, {"env_lights", 50}};
    const auto* css = techniques::findTechnique("css");
    const auto fitted =
        techniques::fittedEnvironmentLights(resolveParams(css->params, block, "test"), s);
    EXPECT_EQ(fitted.stats["lights_fitted"], fitted.lights.size());
    // Lights stop where the map is black: a few cover the patch and its filtered rim.
    EXPECT_LT(fitted.lights.size(), 50u);
    EXPECT_NEAR(fitted.stats["energy_captured"].get<double>(), 1.0, 1e-9);

    const auto* ref = techniques::findTechnique("reference");
    block = {{"name", "reference"}, {"env_samples", 64}};
    const auto sampled =
        techniques::sampledEnvironmentLights(resolveParams(ref->params, block, "test"), s);
    ASSERT_EQ(sampled.lights.size(), 64u);
    double fitted_sum = 0, sampled_sum = 0, first = irradiance(sampled.lights[0]);
    for (const auto& l : fitted.lights) fitted_sum += irradiance(l);
    for (const auto& l : sampled.lights) {
        sampled_sum += irradiance(l);
        EXPECT_NEAR(irradiance(l), first, 1e-3 * first);  // equal shares
    }
    // Both deliver the map's energy (the patch, about 50 x its solid angle).
    EXPECT_NEAR(sampled_sum, fitted_sum, 0.01 * fitted_sum);
}

TEST(EnvironmentLights, ReadsAFittedLightsFile) {
    const char* tmp = std::getenv("PENUMBRA_TEST_TMP");
    const auto dir = std::filesystem::path(tmp ? tmp : "/tmp") / "env_lights_file";
    std::filesystem::create_directories(dir);
    scene::Scene s = skyScene(0.0f);
    s.path = dir / "scene.json";
    s.environment->intensity = 2.0f;
    // Fit the unscaled map (what `penumbra fit-lights` writes), then read it back through the
    // parameter: the same lights, scaled by the scene's intensity.
    scene::FitSettings settings;
    settings.max_lights = 3;
    const auto fit = scene::fitLights(scene::toCubeFaces(*s.environment->image, 32), settings);
    std::ofstream(dir / "lights.json") << scene::lightFitJson(fit, settings, 32).dump();
    const auto* css = techniques::findTechnique("css");
    nlohmann::json block = {{"name", "css"}, {"env_lights_file", "lights.json"}, {"env_lights", 2}};
    const auto read =
        techniques::fittedEnvironmentLights(resolveParams(css->params, block, "test"), s);
    ASSERT_EQ(read.lights.size(), 2u);  // env_lights keeps the first two
    EXPECT_NEAR(read.stats["energy_captured"].get<double>(),
                fit.lights[0].share + fit.lights[1].share, 1e-9);
    const auto direct = techniques::farLight(s, fit.lights[0]);
    EXPECT_NEAR(glm::distance(read.lights[0].radiance(), 2.0f * direct.radiance()), 0.0f,
                1e-3f * glm::length(direct.radiance()));
    block["env_lights_file"] = "missing.json";
    try {
        techniques::fittedEnvironmentLights(resolveParams(css->params, block, "test"), s);
        FAIL() << "expected an InputError";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("technique.env_lights_file"), std::string::npos)
            << e.what();
    }
}
