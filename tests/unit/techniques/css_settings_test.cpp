// `css` CPU-side logic: the parameter table's defaults, the prefilter chosen per light, the
// basis layout, the depth normalisation's margins and its range past the casters.
#include <gtest/gtest.h>

#include "renderer/core/error.h"
#include "renderer/techniques/css/csm_maps.h"
#include "renderer/techniques/css/css_settings.h"
#include "renderer/techniques/technique.h"

using namespace penumbra;
using techniques::css::CsmMaps;

namespace {
techniques::css::CssSettings settingsOf(const nlohmann::json& block) {
    const auto* info = techniques::findTechnique("css");
    EXPECT_NE(info, nullptr);
    return techniques::css::cssSettings(resolveParams(info->params, block, "test"));
}
}  // namespace

TEST(CssSettings, DefaultsAndOverrides) {
    auto s = settingsOf({{"name", "css"}});
    EXPECT_EQ(s.order, 4);
    EXPECT_EQ(s.map_size, 256);
    EXPECT_EQ(s.filter, techniques::css::CssSettings::FilterChoice::Sat);
    EXPECT_EQ(s.self_exclude, 0.25f);
    s = settingsOf({{"name", "css"}, {"order", 16}, {"filter", "auto"}, {"sharpen_a", 0.0}});
    EXPECT_EQ(s.order, 16);
    EXPECT_EQ(s.filter, techniques::css::CssSettings::FilterChoice::Auto);
    EXPECT_EQ(s.sharpen_a, 0.0f);
    EXPECT_THROW(settingsOf({{"name", "css"}, {"order", 17}}), InputError);
    EXPECT_THROW(settingsOf({{"name", "css"}, {"filter", "box"}}), InputError);
    EXPECT_THROW(settingsOf({{"name", "css"}, {"self_exclude", 1.5}}), InputError);
}

TEST(CssSettings, AutoFilterFollowsTheLightsShape) {
    techniques::css::CssSettings s;
    s.filter = techniques::css::CssSettings::FilterChoice::Auto;
    scene::RectLight light;
    light.size = {1.0f, 1.0f};
    EXPECT_EQ(techniques::css::filterFor(s, light), CsmMaps::Filter::Mipmap);
    light.size = {1.0f, 0.5f};
    EXPECT_EQ(techniques::css::filterFor(s, light), CsmMaps::Filter::Sat);
    s.filter = techniques::css::CssSettings::FilterChoice::Mipmap;
    EXPECT_EQ(techniques::css::filterFor(s, light), CsmMaps::Filter::Mipmap);
    s.filter = techniques::css::CssSettings::FilterChoice::Sat;
    light.size = {1.0f, 1.0f};
    EXPECT_EQ(techniques::css::filterFor(s, light), CsmMaps::Filter::Sat);
}

TEST(CssSettings, BasisLayout) {
    // ceil(M/2) CSM layers, as many CSM-Z layers, and one for z and coverage.
    EXPECT_EQ(techniques::css::basisLayers(1), 3);
    EXPECT_EQ(techniques::css::basisLayers(4), 5);
    EXPECT_EQ(techniques::css::basisLayers(5), 7);
    EXPECT_EQ(techniques::css::basisLayers(16), 17);
}

TEST(CssSettings, DepthRangeKeepsMargins) {
    passes::LightWindow w;
    w.near = 2.0f, w.far = 6.0f;
    for (int order : {1, 4, 16}) {
        for (float shift : {0.0f, 0.08f}) {
            const float m = std::min(shift + 0.5f / static_cast<float>(order), 0.3f);
            EXPECT_FLOAT_EQ(techniques::css::depthMargin(order, shift), m);
            const auto r =
                techniques::css::depthRange(w, techniques::css::depthMargin(order, shift));
            // The window's near and far land on m and 1 - m; receivers clamp at 1 - m.
            EXPECT_NEAR((w.near - r.near) / (r.far - r.near), m, 1e-5) << order;
            EXPECT_NEAR((w.far - r.near) / (r.far - r.near), 1.0f - m, 1e-5) << order;
            EXPECT_FLOAT_EQ(r.receiver_max, 1.0f - m);
        }
    }
}

namespace {
passes::Bounds boxBetween(glm::vec3 lo, glm::vec3 hi) {
    passes::Bounds b;
    b.extend(lo), b.extend(hi);
    return b;
}
}  // namespace

TEST(CssSettings, TheDepthRangeEndsAGapPastTheCastersNotAtTheFarthestReceiver) {
    // A light at y = 3 looking straight down (depth = 3 - y); a caster 2-4 deep and a floor
    // slab to 13 deep (a long floor under a low light reaches as deep).
    scene::RectLight light;
    light.position = {0, 3, 0};
    light.target = {0, 0, 0};
    light.up = {0, 0, -1};
    light.size = {0.5f, 0.5f};
    const passes::WorldBox caster[] = {boxBetween({-0.5f, -1.0f, -0.5f}, {0.5f, 1.0f, 0.5f})};
    const passes::WorldBox deep[] = {caster[0], boxBetween({-5, -10, -5}, {5, -1, 5})};
    const passes::WorldBox shallow[] = {caster[0], boxBetween({-5, -1.2f, -5}, {5, -1.1f, 5})};
    const float m = techniques::css::depthMargin(4, 0.08f);
    const auto range = [&](const passes::LightWindow& w) {
        return techniques::css::depthRange(w, m);
    };
    const auto normalised = [](const techniques::css::DepthRange& r, float z) {
        return (z - r.near) / (r.far - r.near);
    };
    // Deep: the far end is the gap, so the farthest caster lies m in front of the receivers'
    // clamp (what a receiver m behind it reads), and the casters keep 1 - 3m of the range
    // instead of 2 / 11 of it.
    const passes::LightWindow cw = passes::windowOf(light, caster);  // 2-4, padded a little
    ASSERT_NEAR(cw.near, 2.0f, 1e-3f);
    ASSERT_NEAR(cw.far, 4.0f, 1e-3f);
    const passes::LightWindow w = techniques::css::mapWindow(light, caster, deep, m);
    EXPECT_EQ(w.near, cw.near);
    EXPECT_LT(w.far, 5.5f);
    const auto r = range(w);
    EXPECT_NEAR(r.receiver_max - normalised(r, cw.far), m, 1e-5f);
    EXPECT_NEAR(normalised(r, cw.far) - normalised(r, cw.near), 1.0f - 3.0f * m, 1e-5f);
    EXPECT_GT(normalised(r, 13.0f), r.receiver_max);  // the floor's far end: clamped
    // Shallow: the scene ends inside the gap, which then ends there (no receiver is clamped).
    const passes::LightWindow ws = techniques::css::mapWindow(light, caster, shallow, m);
    EXPECT_NEAR(ws.far, 4.2f, 1e-3f);
    EXPECT_NEAR(normalised(range(ws), ws.far), 1.0f - m, 1e-5f);
    // A caster of little extent in depth (a card seen face-on): the gap is a quarter of its
    // distance, whatever the margin.
    const passes::WorldBox card[] = {boxBetween({-0.5f, 1.0f, -0.5f}, {0.5f, 1.0f, 0.5f})};
    const passes::LightWindow wc = techniques::css::mapWindow(light, card, deep, m);
    EXPECT_NEAR(wc.far, 1.25f * passes::windowOf(light, card).far, 1e-5f);
}
