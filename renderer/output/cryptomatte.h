// Cryptomatte object mattes (the open Cryptomatte specification, Psyop 2015): names hashed with
// MurmurHash3_x86_32, a manifest of name -> hash, and rank/coverage channels in the EXR.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "renderer/output/image.h"

namespace penumbra::output {

// MurmurHash3_x86_32 of KEY's bytes with SEED (Austin Appleby's reference algorithm).
uint32_t murmurHash3(std::string_view key, uint32_t seed = 0);

// The spec's uint32_to_float32: HASH's bits as a float with the exponent clamped to [1, 254],
// so that the id is never a denormal, inf or NaN.
float cryptomatteId(uint32_t hash);

// `{"NAME":"8-digit lower-case hex hash",...}` for every distinct name.
std::string cryptomatteManifest(const std::vector<std::string>& names);

// Adds the layer LAYER ("CryptoObject") to IMAGE: float channels LAYER00.R/G/B/A holding rank
// 0's id and coverage (R, G) and an empty rank 1 (B, A), and the attributes
// `cryptomatte/<key>/name`, `/hash` ("MurmurHash3_32"), `/conversion` ("uint32_to_float32") and
// `/manifest`, key the first 7 hex digits of LAYER's hash. The pixel's name is NAMES[id] for
// IMAGE's `id` channel (-1: background, no id and coverage 0); its coverage is IMAGE's `A`
// when SAMPLES > 1 (the share of samples on geometry), else 1.
void addCryptomatte(Image& image, const std::string& layer, const std::vector<std::string>& names,
                    int samples);

}  // namespace penumbra::output
