// Mutations of a seed input for penumbra_fuzz: byte and bit edits, interesting integers,
// truncation, chunk deletion and duplication, splices with other seeds, and, in text, numbers
// replaced by huge, negative, fractional or non-finite ones.
#pragma once

#include <cstdint>
#include <random>
#include <vector>

namespace penumbra::fuzz {

using Bytes = std::vector<std::uint8_t>;

// One to four mutations of SEED; POOL gives splice partners.
Bytes mutate(const Bytes& seed, const std::vector<Bytes>& pool, std::mt19937_64& rng);

}  // namespace penumbra::fuzz
