// The tone curve of the PNG preview: exposure in stops, Narkowicz's fit of the ACES filmic
// curve, then the sRGB transfer. Pure functions, so the curve can be tested on its own.
#pragma once

#include <cstdint>

namespace penumbra::output {

// Narkowicz 2015 ACES fit: x(2.51x + 0.03) / (x(2.43x + 0.59) + 0.14), clamped to [0, 1].
// Monotonic non-decreasing for x >= 0 (reaches 1 near x = 7.24); 0 for negative or NaN input.
float filmicCurve(float x);

// The sRGB transfer function (IEC 61966-2-1) of a display-linear value in [0, 1].
float srgbEncode(float linear);

// Scene-linear value -> display-encoded value in [0, 1]: x * 2^exposure, filmic, sRGB.
float toneMap(float linear, float exposure);

// toneMap quantised to 8 bits (round to nearest).
uint8_t toneMap8(float linear, float exposure);

}  // namespace penumbra::output
