// The parameter keys several techniques' tables share (each technique declares its own beside
// its table): one spelling and one type per key, read with Params::get.
#pragma once

#include "renderer/core/params.h"

namespace penumbra::techniques {

inline constexpr IntKey kMapSize{"map_size"};
inline constexpr IntKey kSeed{"seed"};
inline constexpr IntKey kSamples{"samples"};
inline constexpr BoolKey kJitter{"jitter"};
inline constexpr FloatKey kNormalOffset{"normal_offset"};
inline constexpr FloatKey kDepthBias{"depth_bias"};
inline constexpr IntKey kPcf{"pcf"};
inline constexpr IntKey kEnvSamples{"env_samples"};

}  // namespace penumbra::techniques
