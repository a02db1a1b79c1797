// Which channels and pixels a comparison covers: see compare_select.h.
#include "renderer/output/compare_select.h"

#include <algorithm>
#include <string>

#include "renderer/core/did_you_mean.h"

namespace penumbra::output {
namespace {

std::string sizeText(const Image& image) {
    return std::to_string(image.width) + "x" + std::to_string(image.height);
}

}  // namespace

// The channels to compare, in order; throws CompareMismatch.
std::vector<ChannelPair> selectChannels(const Image& ref, const Image& test,
                                        const CompareOptions& options) {
    using Side = CompareMismatch::Side;
    if (ref.width != test.width || ref.height != test.height)
        throw CompareMismatch(Side::Both, "size mismatch: reference is " + sizeText(ref) +
                                              ", test is " + sizeText(test));
    std::vector<std::string> names = options.channels;
    if (names.empty())
        for (const auto& c : ref.channels) names.push_back(c.name);
    std::vector<ChannelPair> pairs;
    for (const auto& name : names) {
        const ImageChannel* r = ref.find(name);
        const ImageChannel* t = test.find(name);
        if (!r) {
            std::vector<std::string> known;
            for (const auto& c : ref.channels) known.push_back(c.name);
            throw CompareMismatch(Side::Reference, "reference has no channel '" + name + "'" +
                                                       didYouMean(name, known));
        }
        if (!t) throw CompareMismatch(Side::Test, "test image has no channel '" + name + "'");
        pairs.push_back({r, t});
    }
    return pairs;
}

// 1 for each pixel that options.ids selects (all without ids); throws CompareMismatch when
// ids are given and REF has no `id` channel or none of its pixels has a listed id.
std::vector<uint8_t> selectPixels(const Image& ref, const CompareOptions& options, size_t pixels) {
    if (options.ids.empty()) return std::vector<uint8_t>(pixels, 1);
    const ImageChannel* id = ref.find("id");
    if (!id)
        throw CompareMismatch(CompareMismatch::Side::Reference,
                              "reference has no channel 'id' (needed by --ids)");
    std::vector<uint8_t> mask(pixels, 0);
    for (size_t i = 0; i < pixels; ++i) {
        const float v = id->pixels[i];
        if (!std::isfinite(v)) continue;
        mask[i] =
            std::find(options.ids.begin(), options.ids.end(), std::lround(v)) != options.ids.end();
    }
    if (std::find(mask.begin(), mask.end(), uint8_t{1}) == mask.end()) {
        std::string message = "--ids ";
        for (size_t i = 0; i < options.ids.size(); ++i) {
            if (i > 0) message += ',';
            message += std::to_string(options.ids[i]);
        }
        message += " selects no pixel (no pixel has such an id)";
        throw CompareMismatch(CompareMismatch::Side::Reference, message);
    }
    return mask;
}

}  // namespace penumbra::output
