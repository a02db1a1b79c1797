// `adaptive`'s map side per light (max_texel): the smallest multiple of 128 whose texel, as
// seen from the light, is no wider than a bound, so that narrow caster windows get coarser maps.
#pragma once

#include <algorithm>
#include <cmath>

namespace penumbra::techniques::adaptive {

// The smallest side a light's maps get, and the step between sides: a window that moves a
// little from frame to frame keeps its side (a new side reallocates the light's map arrays).
inline constexpr int kMinMapSide = 256;
inline constexpr int kMapSideStep = 128;

// The side of a light's maps: the smallest multiple of kMapSideStep from min(kMinMapSide,
// MAX_SIZE), at most MAX_SIZE, whose texel EXTENT / side (EXTENT: the casters' window in tangent
// units, its widest side) is at most MAX_TEXEL; MAX_TEXEL 0: MAX_SIZE.
inline int mapSideFor(int max_size, double max_texel, double extent) {
    if (!(max_texel > 0.0)) return max_size;
    const double needed = std::max(extent / max_texel, 0.0);
    if (!(needed < max_size)) return max_size;  // a huge window (or NaN): the largest
    const int side = int(std::ceil(needed / kMapSideStep)) * kMapSideStep;
    return std::clamp(side, std::min(kMinMapSide, max_size), max_size);
}

}  // namespace penumbra::techniques::adaptive
