// The parameters of `css`: see css_settings.h.
#include "renderer/techniques/css/css_settings.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace penumbra::techniques::css {

CssSettings cssSettings(const Params& p) {
    CssSettings s;
    s.order = p.getInt("order");
    s.map_size = p.getInt("map_size");
    s.filter = p.getEnum(kFilter);
    s.max_aniso = p.getInt("max_aniso");
    s.mip_taps = p.getInt("mip_taps");
    s.search_steps = p.getInt("search_steps");
    s.ring_scale = static_cast<float>(p.getFloat("ring_scale"));
    s.ring_shift = static_cast<float>(p.getFloat("ring_shift"));
    s.sharpen_a = static_cast<float>(p.getFloat("sharpen_a"));
    s.sharpen_b = static_cast<float>(p.getFloat("sharpen_b"));
    s.self_exclude = static_cast<float>(p.getFloat("self_exclude"));
    return s;
}

CsmMaps::Filter filterFor(const CssSettings& s, const scene::RectLight& light) {
    switch (s.filter) {
        case FilterChoice::Mipmap:
            return CsmMaps::Filter::Mipmap;
        case FilterChoice::Sat:
            return CsmMaps::Filter::Sat;
        case FilterChoice::Auto:
            break;
    }
    const float a = light.size.x, b = light.size.y;
    const bool square = std::fabs(a - b) <= 1e-4f * std::max(a, b);
    return square ? CsmMaps::Filter::Mipmap : CsmMaps::Filter::Sat;
}

}  // namespace penumbra::techniques::css
