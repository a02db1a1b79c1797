// The parameters of `css`: see css_settings.h.
#include "renderer/techniques/css/css_settings.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "renderer/core/memory_limit.h"

namespace penumbra::techniques::css {

CssSettings cssSettings(const Params& p) {
    CssSettings s;
    s.order = p.get(kOrder);
    s.map_size = p.get(kMapSize);
    s.filter = p.getEnum(kFilter);
    s.blocker_depth = p.getEnum(kBlockerDepth);
    s.middle_at = static_cast<float>(p.get(kMiddleAt));
    s.max_aniso = p.get(kMaxAniso);
    s.mip_taps = p.get(kMipTaps);
    s.search_steps = p.get(kSearchSteps);
    s.ring_scale = static_cast<float>(p.get(kRingScale));
    s.ring_shift = static_cast<float>(p.get(kRingShift));
    s.sharpen_a = static_cast<float>(p.get(kSharpenA));
    s.sharpen_b = static_cast<float>(p.get(kSharpenB));
    s.self_exclude = static_cast<float>(p.get(kSelfExclude));
    s.interpolate = static_cast<float>(p.get(kInterpolate));
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

MemoryTerms memoryTerms(const Params& p, std::uint64_t) {
    const int map = p.get(kMapSize);
    const auto m = static_cast<std::uint64_t>(map);
    const int order = p.get(kOrder);
    const auto layers = 2 * static_cast<std::uint64_t>((order + 1) / 2) + 1;
    const FilterChoice filter = p.getEnum(kFilter);
    const std::uint64_t basis = saturatingProduct({m, m, 16, layers});
    MemoryTerms out;
    // With summed-area tables alone the basis goes straight into the tables' rows.
    if (filter != FilterChoice::Sat)
        out.push_back({"technique.order",
                       "the basis images (" + squareText(map) + " x " + std::to_string(layers) +
                           " RGBA32F, mipmapped)",
                       basis + basis / 3, true});
    if (filter != FilterChoice::Mipmap)
        out.push_back({"technique.order",
                       "the summed-area table array (" + squareText(map + 1) + " x " +
                           std::to_string(layers) + " RGBA32F)",
                       saturatingProduct({m + 1, m + 1, 16, layers}), true});
    const bool middle = p.getEnum(kBlockerDepth) == BlockerDepth::Middle;
    out.push_back({"technique.map_size",
                   middle ? "the shadow maps (nearest and farthest)" : "the shadow map",
                   saturatingProduct({m, m, middle ? 8u : 4u})});
    return out;
}

}  // namespace penumbra::techniques::css
