// One table-driven test over every registered technique (allTechniques()), so a technique is
// covered the moment it is registered: it renders with no GL error, its visibility is finite and
// in [0, 1], its beauty finite and non-negative, two renders give the same bytes, and its error
// stays within the bound stated for it below against a closed form and against `exact`.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <initializer_list>
#include <map>
#include <sstream>
#include <string>

#include "gl_test_env.h"
#include "renderer/techniques/technique.h"

using penumbra::testing::channel;
using penumbra::testing::renderScene;

namespace {

// Each technique's bounds, at its defaults and 128 x 96, on three small scenes:
// - closed_form: the shadow-region MAE of visibility over the floor against the closed form of
//   a 0.8 m square occluder (role occluder) under a parallel 1 m square light;
// - both_box: the floor's shadow-region MAE against `exact` (N = 32) under a box of the default
//   role `both` lit by a 0.5 m light, i.e. the floor hidden from the light's centre by a caster;
// - tilted_light_union: the floor's shadow-region MAE against `exact` (N = 32) on random scene
//   64 of scripts/random-scenes (nobody tuned on it): a tilted light whose casters' union box
//   reaches behind the light's plane, though no caster does. Windows fitted to that box had a
//   near plane at 1e-4 of the far and hit the 80-degree clamp: css found no blocker and lit
//   the whole floor (0.31 at 160 x 120), the others lost resolution.
// - occluder_ball: the shadow-region MAE of visibility over a ball of role `occluder` (casts,
//   receives nothing) lit from the side, against `exact` (N = 32): nothing shadows it, but its
//   own surface hides the light below each point's tangent plane, on its dark half and across
//   the band where the light crosses its horizon. `ssm` and `bitmask` wrote 1 there (0.77).
// - strip_light: the floor's shadow-region MAE against `exact` (N = 32) under a 1.5 x 0.015
//   light (a tube, 100:1) over a box and a thin bar. `ssm` and `bitmask` rendered their casters
//   through a window stretched to the light's aspect, between whose texels they fell (0.27 and
//   0.30 at 256 x 192, the box's edge across the strip in stairs); now texels of at most 2:1.
// Each bound is the value measured when it was written (printed by this test; run
// `build/tests/penumbra_gl_tests --gtest_filter='Registered/EveryTechnique*'`), times 1.25 and
// at least 0.002 above it: room for another rasteriser's texel edges, not for a regression.
// A technique missing here fails: state its bounds when you register it.
struct Bounds {
    double closed_form;
    double both_box;
    double tilted_union;
    double occluder;
    double strip;
};
const std::map<std::string, Bounds>& bounds() {
    static const std::map<std::string, Bounds> table = {
        // hard is the baseline: one sample, so the whole penumbra is wrong (measured 0.233,
        // 0.166 and 0.221); its bounds say only that it draws the shadow where it belongs.
        // On occluder_ball its one sample at the light's centre is lit or hidden (0.1044);
        // strip_light 0.2007.
        {"hard", {0.29, 0.21, 0.28, 0.131, 0.251}},
        // reference measured 0.0047, 0.0034, 0.0141, 0.0023, 0.0050.
        {"reference", {0.0067, 0.0054, 0.0177, 0.0043, 0.0070}},
        // exact at its default N = 16 against the closed form and against exact N = 32: the
        // noise of 16 x 16 stratified rays (measured 0.0049, 0.0036, 0.0050, 0.0025, 0.0045).
        {"exact", {0.0069, 0.0056, 0.0070, 0.0045, 0.0065}},
        // adaptive measured 0.0067, 0.0106, 0.0140, 0.0040, 0.0064.
        {"adaptive", {0.0178, 0.0148, 0.0175, 0.0060, 0.0084}},
        // ssm back-projects each occluder texel onto the light exactly; with the default light
        // sample masks (256 samples) a flat occluder parallel to the light is exact to their
        // quantisation (measured 0.0075; below 0.0001 with the paper's sum, accumulate=area).
        // both_box: 0.0039 (0.0173 with the sum two-sided, the far side's map holding the
        // box's walls, back faces from the light's centre, as flat patches). tilted_light_union:
        // 0.0329. occluder_ball: 0.0008. strip_light: 0.0115 (0.2835 before).
        {"ssm", {0.0095, 0.0059, 0.0412, 0.0028, 0.0144}},
        // bitmask measured 0.0043, 0.0038, 0.0442, 0.0023; strip_light 0.0121 (0.2857 before).
        {"bitmask", {0.0063, 0.0125, 0.0553, 0.0043, 0.0151}},
        // css assumes one blocker depth per kernel; the box's sides break that on both_box
        // (Annen et al. 2008, section 5; measured 0.0092, 0.0307). tilted_light_union: 0.0834,
        // occluder_ball: 0.0019, strip_light 0.0275.
        {"css", {0.0115, 0.0384, 0.1043, 0.0039, 0.0344}},
    };
    return table;
}

// NAME's bounds, or null and a failure naming where to state them.
const Bounds* boundsOf(const std::string& name) {
    const auto it = bounds().find(name);
    if (it != bounds().end()) return &it->second;
    ADD_FAILURE() << "technique " << name << " has no bounds in tests/gl/every_technique_test.cpp";
    return nullptr;
}

const std::vector<penumbra::scene::Override> kSize = {{"image.width", "128"},
                                                      {"image.height", "96"}};

std::vector<penumbra::scene::Override> withTechnique(const std::string& name) {
    auto o = kSize;
    o.push_back({"technique", R"({"name": ")" + name + R"("})"});
    return o;
}

// `exact` (N = 32) on SCENE, rendered once per scene.
const penumbra::output::Image& exactOf(const std::string& scene) {
    static std::map<std::string, penumbra::output::Image> images;
    auto it = images.find(scene);
    if (it == images.end()) {
        auto o = kSize;
        o.push_back({"technique", penumbra::testing::kGroundTruth});
        it = images.emplace(scene, renderScene(scene, o)).first;
    }
    return it->second;
}

bool sameBytes(const std::vector<float>& a, const std::vector<float>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

class EveryTechniqueGL : public ::testing::TestWithParam<std::string> {};

TEST_P(EveryTechniqueGL, RendersValidDeterministicVisibilityWithinItsBounds) {
    const std::string name = GetParam();
    const Bounds* bound = boundsOf(name);
    ASSERT_NE(bound, nullptr);

    // renderScene fails on any GL error raised by the render.
    const auto img = renderScene("closed_form.json", withTechnique(name));
    const auto& v = channel(img, "visibility");
    long out_of_range = 0;
    for (float x : v) out_of_range += !(std::isfinite(x) && x >= 0.0f && x <= 1.0f);
    EXPECT_EQ(out_of_range, 0) << "visibility outside [0, 1] or not finite";
    long bad_beauty = 0;
    for (const char* c : {"R", "G", "B"})
        for (float x : channel(img, c)) bad_beauty += !(std::isfinite(x) && x >= 0.0f);
    EXPECT_EQ(bad_beauty, 0) << "beauty negative or not finite";

    // Determinism on the scene whose caster is `both` (every technique's object path); ssm's
    // default maps on closed_form cost about 24 s on llvmpipe (65536 micro-patches filling
    // about 9800 texels each), so that scene renders once.
    const auto box = renderScene("both_box.json", withTechnique(name));
    const auto again = renderScene("both_box.json", withTechnique(name));
    for (const char* c : {"visibility", "R", "G", "B"})
        EXPECT_TRUE(sameBytes(channel(box, c), channel(again, c))) << c << " differs";

    const double closed = penumbra::testing::closedFormShadowMae(img, 0.5, 500);
    const double both = penumbra::testing::floorShadowMae(exactOf("both_box.json"), box, 300);
    const double tilted = penumbra::testing::floorShadowMae(
        exactOf("tilted_light_union.json"),
        renderScene("tilted_light_union.json", withTechnique(name)), 300);
    std::printf(
        "%s: closed form %.4f (bound %.4f), both_box vs exact %.4f (bound %.4f), "
        "tilted_light_union vs exact %.4f (bound %.4f)\n",
        name.c_str(), closed, bound->closed_form, both, bound->both_box, tilted,
        bound->tilted_union);
    EXPECT_LE(closed, bound->closed_form);
    EXPECT_LE(both, bound->both_box);
    EXPECT_LE(tilted, bound->tilted_union);
}

TEST_P(EveryTechniqueGL, AnOccluderHidesTheLightBelowItsOwnSurface) {
    const std::string name = GetParam();
    const Bounds* bound = boundsOf(name);
    ASSERT_NE(bound, nullptr);
    const double mae = penumbra::testing::objectShadowMae(
        exactOf("occluder_ball.json"), renderScene("occluder_ball.json", withTechnique(name)), 1,
        300);
    std::printf("%s: occluder_ball's ball vs exact %.4f (bound %.4f)\n", name.c_str(), mae,
                bound->occluder);
    EXPECT_LE(mae, bound->occluder);
}

TEST_P(EveryTechniqueGL, AStripLightsShadowsFollowExact) {
    const std::string name = GetParam();
    const Bounds* bound = boundsOf(name);
    ASSERT_NE(bound, nullptr);
    const double mae = penumbra::testing::floorShadowMae(
        exactOf("strip_light.json"), renderScene("strip_light.json", withTechnique(name)), 300);
    std::printf("%s: strip_light's floor vs exact %.4f (bound %.4f)\n", name.c_str(), mae,
                bound->strip);
    EXPECT_LE(mae, bound->strip);
}

// box_floating.json (the conformance scene) with every length times S: the camera, the light
// and the box's transform, as a scene in centimetres or kilometres would be.
std::vector<penumbra::scene::Override> scaledBoxFloating(const std::string& name, float s) {
    const auto text = [](std::initializer_list<float> values, bool list) {
        std::ostringstream out;
        out << (list ? "[" : "");
        for (const float* x = values.begin(); x != values.end(); ++x)
            out << (x == values.begin() ? "" : ", ") << *x;
        out << (list ? "]" : "");
        return out.str();
    };
    const auto v = [&](float x, float y, float z) { return text({x * s, y * s, z * s}, true); };
    std::ostringstream box;
    box << R"({"translate": )" << v(0.0f, 0.7f, 0.0f) << R"(, "rotate": [0, 20, 0], "scale": )" << s
        << "}";
    return {{"technique", R"({"name": ")" + name + R"("})"},
            {"camera.position", v(2.6f, 2.4f, 3.4f)},
            {"camera.target", v(0.0f, 0.4f, 0.0f)},
            {"camera.near", text({0.05f * s}, false)},
            {"camera.far", text({60.0f * s}, false)},
            {"lights.0.position", v(0.0f, 3.0f, 0.0f)},
            {"lights.0.target", v(0.0f, 0.0f, 0.0f)},
            {"lights.0.size", text({s, s}, true)},
            {"objects.0.transform", R"({"scale": )" + text({s}, false) + "}"},
            {"objects.1.transform", box.str()}};
}

TEST_P(EveryTechniqueGL, AScaledSceneCastsTheSameShadows) {
    // Nothing in a technique may depend on the unit of length. Two did, through float
    // coincidences that come and go with the scale: the closed-form share of the light above a
    // face parallel to it (light_horizon.glsl: `ssm` and `css` drew rows of 0 on lit faces;
    // LightHorizonGL) and the light-centre maps' near clip plane, on which the nearest caster's
    // face lies (LightWindow::viewProj: at 26 and 30 `css`'s map lost the box's top, which then
    // shadowed itself). Measured after the fixes: mean |difference| at most 1e-5 (float noise).
    const std::string name = GetParam();
    const auto unit = renderScene("box_floating.json", scaledBoxFloating(name, 1.0f));
    const auto& one = channel(unit, "visibility");
    for (float s : {0.01f, 30.0f}) {
        const auto img = renderScene("box_floating.json", scaledBoxFloating(name, s));
        const auto& scaled = channel(img, "visibility");
        ASSERT_EQ(scaled.size(), one.size());
        double sum = 0.0;
        for (size_t i = 0; i < one.size(); ++i) sum += std::fabs(double(scaled[i]) - one[i]);
        const double mean = sum / double(one.size());
        std::printf("%s: box_floating x %g against x 1: mean |difference| %.2g\n", name.c_str(),
                    double(s), mean);
        EXPECT_LE(mean, 1e-4) << "scale " << s;
    }
}

std::vector<std::string> registeredNames() {
    std::vector<std::string> names;
    for (const auto& t : penumbra::techniques::allTechniques()) names.emplace_back(t.name);
    return names;
}

INSTANTIATE_TEST_SUITE_P(Registered, EveryTechniqueGL, ::testing::ValuesIn(registeredNames()),
                         [](const auto& param_info) { return param_info.param; });

}  // namespace
