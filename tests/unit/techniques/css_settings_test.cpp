// `css` CPU-side logic: the parameter table's defaults, the prefilter chosen per light, the
// basis layout and the depth normalisation's margins.
#include <gtest/gtest.h>

#include "renderer/core/error.h"
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
            const auto r = techniques::css::depthRange(w, order, shift);
            const float m = std::min(shift + 0.5f / static_cast<float>(order), 0.3f);
            // The casters' near and the scene's far land on m and 1 - m.
            EXPECT_NEAR((w.near - r.near) / (r.far - r.near), m, 1e-5) << order;
            EXPECT_NEAR((w.far - r.near) / (r.far - r.near), 1.0f - m, 1e-5) << order;
        }
    }
}
