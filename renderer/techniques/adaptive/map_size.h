// `adaptive`'s map side per light (max_texel): the smallest power of two whose texel, as seen
// from the light, is no wider than a bound, so that narrow caster windows get coarser maps.
#pragma once

#include <algorithm>

namespace penumbra::techniques::adaptive {

// The smallest side a light's maps get.
inline constexpr int kMinMapSide = 256;

// The side of a light's maps: the smallest power of two from min(kMinMapSide, MAX_SIZE), at most
// MAX_SIZE, whose texel EXTENT / side (EXTENT: the casters' window in tangent units, its widest
// side) is at most MAX_TEXEL; MAX_TEXEL 0: MAX_SIZE.
inline int mapSideFor(int max_size, double max_texel, double extent) {
    if (!(max_texel > 0.0)) return max_size;
    int side = std::min(kMinMapSide, max_size);
    while (side < max_size && extent / side > max_texel) side *= 2;
    return std::min(side, max_size);
}

}  // namespace penumbra::techniques::adaptive
