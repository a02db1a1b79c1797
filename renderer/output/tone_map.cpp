// The preview tone curve: see tone_map.h.
#include "renderer/output/tone_map.h"

#include <algorithm>
#include <cmath>

namespace penumbra::output {

float filmicCurve(float x) {
    if (!(x > 0.0f)) return 0.0f;  // negative, zero and NaN
    if (x >= 8.0f) return 1.0f;    // the curve reaches 1 near x = 7.24; also catches inf
    const float y = (x * (2.51f * x + 0.03f)) / (x * (2.43f * x + 0.59f) + 0.14f);
    return std::clamp(y, 0.0f, 1.0f);
}

float srgbEncode(float linear) {
    if (!(linear > 0.0f)) return 0.0f;
    if (linear >= 1.0f) return 1.0f;  // exactly: 1.055f - 0.055f rounds below 1
    if (linear <= 0.0031308f) return 12.92f * linear;
    return std::min(1.0f, 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f);
}

float toneMap(float linear, float exposure) {
    return srgbEncode(filmicCurve(linear * std::exp2(exposure)));
}

uint8_t toneMap8(float linear, float exposure) {
    return static_cast<uint8_t>(std::lround(toneMap(linear, exposure) * 255.0f));
}

}  // namespace penumbra::output
