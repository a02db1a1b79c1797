// Environment-map light fitting on synthetic maps: the equirectangular and cube conventions,
// energy conservation of the resampling, one bright patch -> one light in its direction
// carrying nearly all the energy, shapes, thresholds, and the JSON round trip.
#include <gtest/gtest.h>

#include <cmath>

#include "renderer/core/error.h"
#include "renderer/scene/light_fitting.h"

using namespace penumbra;
using namespace penumbra::scene;

namespace {
constexpr double kPi = 3.14159265358979323846;

// A W x H map of radiance BACKGROUND with a patch of radiance BRIGHT of half-angle HALF
// (radians) around direction CENTRE.
EnvironmentImage map(int w, int h, float background, float bright, glm::vec3 centre, float half) {
    EnvironmentImage img;
    img.width = w, img.height = h;
    img.rgb.resize(size_t(w * h * 3));
    centre = glm::normalize(centre);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const glm::vec3 d = equirectDirection((x + 0.5f) / w, (y + 0.5f) / h);
            const float v = std::acos(std::clamp(glm::dot(d, centre), -1.0f, 1.0f)) < half
                                ? bright
                                : background;
            for (int c = 0; c < 3; ++c) img.rgb[size_t((y * w + x) * 3 + c)] = v;
        }
    return img;
}
}  // namespace

TEST(LightFitting, EquirectConventionRoundTrips) {
    EXPECT_NEAR(glm::distance(equirectDirection(0.5f, 0.5f), glm::vec3(0, 0, -1)), 0.0f, 1e-5f);
    EXPECT_NEAR(glm::distance(equirectDirection(0.75f, 0.5f), glm::vec3(1, 0, 0)), 0.0f, 1e-5f);
    EXPECT_NEAR(equirectDirection(0.3f, 0.0f).y, 1.0f, 1e-5f);
    for (float u : {0.1f, 0.4f, 0.9f})
        for (float v : {0.2f, 0.5f, 0.8f}) {
            const glm::vec2 uv = equirectCoordinates(equirectDirection(u, v));
            EXPECT_NEAR(uv.x, u, 1e-5f);
            EXPECT_NEAR(uv.y, v, 1e-5f);
        }
}

TEST(LightFitting, CubeTexelsCoverTheSphere) {
    double sum = 0;
    for (int j = 0; j < 16; ++j)
        for (int i = 0; i < 16; ++i) sum += cubeTexelSolidAngle(16, i, j);
    EXPECT_NEAR(6 * sum, 4 * kPi, 1e-9);
    // A constant map of radiance 1 carries 4 pi of energy after resampling.
    const CubeFaces faces = toCubeFaces(map(128, 64, 1.0f, 1.0f, {0, 0, -1}, 0.1f), 16);
    EXPECT_NEAR(faces.totalLuminance(), 4 * kPi, 1e-3);
}

TEST(LightFitting, OneBrightPatchBecomesOneLight) {
    // A 10-degree disc 1000 times brighter than a dim sky, in the middle of the -Z face.
    const glm::vec3 sun = glm::normalize(glm::vec3(0.1f, 0.2f, -1.0f));
    const auto img = map(512, 256, 0.01f, 10.0f, sun, float(5 * kPi / 180));
    FitSettings s;
    s.max_lights = 1;
    const LightFit fit = fitLights(toCubeFaces(img, 32), s);
    ASSERT_EQ(fit.lights.size(), 1u);
    const auto& l = fit.lights[0];
    EXPECT_EQ(l.face, 5);
    // The fitted rectangle's centre is within a texel (about 3.6 degrees) of the disc's centre.
    EXPECT_LT(std::acos(std::min(1.0f, glm::dot(l.direction, sun))) * 180 / kPi, 3.0);
    // The disc holds 10 * 0.0239 sr = 0.239 of 0.239 + 0.01 * 4 pi = 0.365: the light takes
    // the disc (all of it: the rectangle grows to its edge) and the sky under it.
    EXPECT_GT(l.share, 0.6);
    EXPECT_NEAR(fit.captured, l.share, 1e-12);
    EXPECT_NEAR(glm::dot(l.right, l.direction), 0.0f, 1e-5f);
    EXPECT_NEAR(glm::dot(l.up, l.direction), 0.0f, 1e-5f);
    // Without a limit every texel is covered and all the energy is captured.
    const LightFit all = fitLights(toCubeFaces(img, 32), FitSettings{});
    EXPECT_NEAR(all.captured, 1.0, 1e-9);
    EXPECT_GT(all.lights.size(), 6u);
}

TEST(LightFitting, SquaresStaySquareAndThresholdSetsTheSize) {
    const auto img = map(256, 128, 1.0f, 1.0f, {0, 1, 0}, 0.1f);  // uniform
    FitSettings square;
    square.square = true;
    for (const auto& l : fitLights(toCubeFaces(img, 16), square).lights)
        EXPECT_EQ(l.x1 - l.x0, l.y1 - l.y0);
    // On a uniform face a side grows while 1 / (w + 1) > t: a lower t gives fewer, larger lights.
    FitSettings coarse, fine;
    coarse.threshold = 0.05, fine.threshold = 0.3;
    const auto a = fitLights(toCubeFaces(img, 16), coarse);
    const auto b = fitLights(toCubeFaces(img, 16), fine);
    EXPECT_LT(a.lights.size(), b.lights.size());
    EXPECT_NEAR(a.captured, 1.0, 1e-9);
    EXPECT_NEAR(b.captured, 1.0, 1e-9);
}

TEST(LightFitting, ResidualLeavesEnergyForLaterLights) {
    const auto img = map(256, 128, 0.5f, 20.0f, {1, 0.3f, 0.2f}, 0.2f);
    FitSettings s;
    s.max_lights = 3;
    s.residual = 0.5;
    const LightFit fit = fitLights(toCubeFaces(img, 16), s);
    double sum = 0;
    for (const auto& l : fit.lights) sum += l.share;
    EXPECT_NEAR(sum, fit.captured, 1e-12);
    EXPECT_LT(fit.captured, 1.0);
}

TEST(LightFitting, JsonRoundTripAndErrors) {
    const auto img = map(256, 128, 0.2f, 5.0f, {0, 0.5f, 1}, 0.3f);
    FitSettings s;
    s.max_lights = 4;
    const LightFit fit = fitLights(toCubeFaces(img, 16), s);
    const LightFit back = lightFitFromJson(lightFitJson(fit, s, 16), "fit.json");
    ASSERT_EQ(back.lights.size(), fit.lights.size());
    for (size_t i = 0; i < fit.lights.size(); ++i) {
        EXPECT_NEAR(glm::distance(back.lights[i].direction, fit.lights[i].direction), 0.0f, 1e-6f);
        EXPECT_NEAR(glm::distance(back.lights[i].radiance(), fit.lights[i].radiance()), 0.0f,
                    1e-4f);
        EXPECT_NEAR(back.lights[i].extent.x, fit.lights[i].extent.x, 1e-5f);
    }
    auto j = lightFitJson(fit, s, 16);
    j["lights"][1]["radiance"] = "red";
    try {
        lightFitFromJson(j, "fit.json");
        FAIL() << "expected an InputError";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("fit.json: lights.1.radiance"), std::string::npos)
            << e.what();
    }
    EXPECT_THROW(lightFitFromJson({{"schema", "other"}}, "x"), InputError);
}
