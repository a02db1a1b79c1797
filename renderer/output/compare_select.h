// Which channels and pixels a comparison covers (compare.cpp): pairs of same-named channels,
// and a mask of the pixels --ids selects; mismatches throw CompareMismatch.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "renderer/output/compare.h"

namespace penumbra::output {

struct ChannelPair {
    const ImageChannel* ref;
    const ImageChannel* test;
};

// The channels to compare, in order; throws CompareMismatch.
std::vector<ChannelPair> selectChannels(const Image& ref, const Image& test,
                                        const CompareOptions& options);

// 1 for each pixel that options.ids selects (all without ids); throws CompareMismatch when
// ids are given and REF has no `id` channel or none of its pixels has a listed id.
std::vector<uint8_t> selectPixels(const Image& ref, const CompareOptions& options, size_t pixels);

}  // namespace penumbra::output
