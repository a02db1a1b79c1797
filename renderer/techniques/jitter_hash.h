// A small integer hash (splitmix64 finaliser) to [0, 1): deterministic jitter of light samples,
// the same on every run, machine and process.
#pragma once

#include <cstdint>

namespace penumbra::techniques {

inline float hashToUnit(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    std::uint64_t x = (std::uint64_t(a) << 42) ^ (std::uint64_t(b) << 21) ^ c;
    x += 0x9E3779B97F4A7C15ull;
    x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
    x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
    x ^= x >> 31;
    return static_cast<float>(x >> 40) / static_cast<float>(1u << 24);
}

}  // namespace penumbra::techniques
