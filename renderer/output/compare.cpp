// Image comparison: see compare.h. One pass per channel over the absolute differences, with a
// per-pixel flag array for the fail/warn pixel counts and one buffer for the percentiles.
#include "renderer/output/compare.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "renderer/core/did_you_mean.h"

namespace penumbra::output {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

struct ChannelPair {
    const ImageChannel* ref;
    const ImageChannel* test;
};

std::string sizeText(const Image& image) {
    return std::to_string(image.width) + "x" + std::to_string(image.height);
}

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

// |a - b|: 0 for equal values, equal infinities included (the background's Z = +inf), else
// infinite when either is NaN or inf.
double absoluteDifference(float a, float b) {
    if (a == b) return 0.0;
    if (!std::isfinite(a) || !std::isfinite(b)) return kInfinity;
    return std::fabs(static_cast<double>(a) - static_cast<double>(b));
}

// Nearest-rank 99th percentile: the smallest value with at least 99% of the values at or
// below it. Reorders [first, last). 0 for an empty range.
double percentile99(std::vector<float>::iterator first, std::vector<float>::iterator last) {
    const auto n = static_cast<size_t>(last - first);
    if (n == 0) return 0.0;
    const size_t rank = (99 * n + 99) / 100;  // ceil(0.99 n), 1-based
    auto nth = first + static_cast<std::ptrdiff_t>(rank - 1);
    std::nth_element(first, nth, last);
    return *nth;
}

nlohmann::json number(double value) {
    return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(nullptr);
}

template <typename T>
nlohmann::json optionalJson(const std::optional<T>& value) {
    return value ? number(static_cast<double>(*value)) : nlohmann::json(nullptr);
}

void shadowRegion(const Image& ref, const Image& test, const std::vector<uint8_t>& mask,
                  CompareResult& result) {
    const ImageChannel* r = ref.find("visibility");
    const ImageChannel* t = test.find("visibility");
    if (!r || !t) return;
    double sum = 0;
    long count = 0;
    for (size_t i = 0; i < r->pixels.size(); ++i) {
        if (!mask[i]) continue;
        const float a = r->pixels[i], b = t->pixels[i];
        if (!std::isfinite(a) || !std::isfinite(b)) continue;
        if (a < kShadowVisibility || b < kShadowVisibility) {
            sum += std::fabs(static_cast<double>(a) - static_cast<double>(b));
            ++count;
        }
    }
    result.shadow_pixels = count;
    if (count > 0) result.shadow_mae = sum / static_cast<double>(count);
}

}  // namespace

const char* verdictName(Verdict verdict) {
    switch (verdict) {
        case Verdict::Pass:
            return "pass";
        case Verdict::Warn:
            return "warn";
        case Verdict::Fail:
            return "fail";
    }
    return "fail";
}

CompareResult compareImages(const Image& ref, const Image& test, const CompareOptions& options) {
    const std::vector<ChannelPair> pairs = selectChannels(ref, test, options);
    CompareResult result;
    result.options = options;
    result.width = ref.width;
    result.height = ref.height;
    const size_t width = static_cast<size_t>(std::max(ref.width, 0));
    const size_t pixels = width * static_cast<size_t>(std::max(ref.height, 0));
    const std::vector<uint8_t> mask = selectPixels(ref, options, pixels);
    result.pixels = std::count(mask.begin(), mask.end(), uint8_t(1));

    enum : uint8_t { kFailed = 1, kWarned = 2 };
    std::vector<uint8_t> flags(pixels, 0);
    std::vector<float> finite;  // finite differences, one contiguous block per channel
    finite.reserve(pixels * pairs.size());
    std::vector<size_t> blockStart;
    double sum = 0, sumSquares = 0;

    for (const auto& pair : pairs) {
        ChannelMetrics m;
        m.name = pair.ref->name;
        result.channels.push_back(m.name);
        blockStart.push_back(finite.size());
        double channelSum = 0, channelSquares = 0;
        for (size_t i = 0; i < pixels; ++i) {
            if (!mask[i]) continue;
            const double d = absoluteDifference(pair.ref->pixels[i], pair.test->pixels[i]);
            if (d > options.fail) flags[i] |= kFailed;
            if (d > options.warn) flags[i] |= kWarned;
            if (d > m.max) {
                m.max = d;
                m.max_x = static_cast<int>(i % width);
                m.max_y = static_cast<int>(i / width);
            }
            if (std::isinf(d)) {
                ++m.nonfinite;
                continue;
            }
            channelSum += d;
            channelSquares += d * d;
            finite.push_back(static_cast<float>(d));
        }
        const size_t n = finite.size() - blockStart.back();
        if (n > 0) {
            m.mae = channelSum / static_cast<double>(n);
            m.rmse = std::sqrt(channelSquares / static_cast<double>(n));
        }
        m.p99 = percentile99(finite.begin() + static_cast<std::ptrdiff_t>(blockStart.back()),
                             finite.end());
        sum += channelSum;
        sumSquares += channelSquares;
        result.nonfinite += m.nonfinite;
        if (result.per_channel.empty() || m.max > result.max) {
            result.max = m.max;
            result.max_x = m.max_x;
            result.max_y = m.max_y;
            result.max_channel = m.name;
        }
        result.per_channel.push_back(std::move(m));
    }

    if (!finite.empty()) {
        result.mae = sum / static_cast<double>(finite.size());
        result.rmse = std::sqrt(sumSquares / static_cast<double>(finite.size()));
    }
    result.p99 = percentile99(finite.begin(), finite.end());
    for (uint8_t f : flags) {
        result.fail_pixels += (f & kFailed) ? 1 : 0;
        result.warn_pixels += (f & kWarned) ? 1 : 0;
    }
    const double n = static_cast<double>(result.pixels);
    if (result.pixels > 0) {
        result.fail_fraction = static_cast<double>(result.fail_pixels) / n;
        result.warn_fraction = static_cast<double>(result.warn_pixels) / n;
    }
    shadowRegion(ref, test, mask, result);

    // idiff's rule: more failing pixels than allowed, or any difference above hardfail.
    if (static_cast<double>(result.fail_pixels) > options.fail_percent / 100.0 * n ||
        (options.hard_fail && result.max > *options.hard_fail))
        result.verdict = Verdict::Fail;
    else if (static_cast<double>(result.warn_pixels) > options.warn_percent / 100.0 * n)
        result.verdict = Verdict::Warn;
    else
        result.verdict = Verdict::Pass;
    return result;
}

Image differenceImage(const Image& ref, const Image& test, const CompareOptions& options) {
    const std::vector<ChannelPair> pairs = selectChannels(ref, test, options);
    Image diff;
    diff.width = ref.width;
    diff.height = ref.height;
    diff.channels.reserve(pairs.size());
    const std::vector<uint8_t> mask = selectPixels(
        ref, options, size_t(std::max(ref.width, 0)) * size_t(std::max(ref.height, 0)));
    for (const auto& pair : pairs) {
        ImageChannel& c = diff.add(pair.ref->name, PixelType::Float);
        for (size_t i = 0; i < c.pixels.size(); ++i)
            c.pixels[i] = mask[i] ? static_cast<float>(absoluteDifference(pair.ref->pixels[i],
                                                                          pair.test->pixels[i]))
                                  : 0.0f;
    }
    return diff;
}

nlohmann::json CompareResult::toJson() const {
    nlohmann::json perChannel = nlohmann::json::array();
    for (const auto& m : per_channel)
        perChannel.push_back({{"name", m.name},
                              {"mae", number(m.mae)},
                              {"rmse", number(m.rmse)},
                              {"max", number(m.max)},
                              {"max_x", m.max_x},
                              {"max_y", m.max_y},
                              {"p99", number(m.p99)},
                              {"nonfinite", m.nonfinite}});
    return {
        {"verdict", verdictName(verdict)},
        {"width", width},
        {"height", height},
        {"pixels", pixels},
        {"channels", channels},
        {"mae", number(mae)},
        {"rmse", number(rmse)},
        {"max", number(max)},
        {"max_x", max_x},
        {"max_y", max_y},
        {"max_channel", max_channel},
        {"p99", number(p99)},
        {"nonfinite", nonfinite},
        {"fail_pixels", fail_pixels},
        {"fail_fraction", fail_fraction},
        {"warn_pixels", warn_pixels},
        {"warn_fraction", warn_fraction},
        {"shadow_mae", optionalJson(shadow_mae)},
        {"shadow_pixels", shadow_pixels ? nlohmann::json(*shadow_pixels) : nlohmann::json()},
        {"thresholds",
         {{"fail", options.fail},
          {"fail_percent", options.fail_percent},
          {"warn", options.warn},
          {"warn_percent", options.warn_percent},
          {"hard_fail", optionalJson(options.hard_fail)}}},
        {"per_channel", perChannel},
    };
}

}  // namespace penumbra::output
