// Image comparison: see compare.h. One pass per channel over the absolute differences, with a
// per-pixel flag array for the fail/warn pixel counts and one buffer for the percentiles.
#include "renderer/output/compare.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "renderer/output/compare_select.h"

namespace penumbra::output {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

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

enum : uint8_t { kFailed = 1, kWarned = 2 };

// What the channels of one comparison add up: per-pixel fail/warn flags, and the finite
// differences (one contiguous block per channel) with their sum and sum of squares.
struct Totals {
    std::vector<uint8_t> flags;
    std::vector<float> finite;
    double sum = 0, sum_squares = 0;
};

// PAIR's metrics over the pixels MASK selects; flags its failing and warning pixels and adds its
// finite differences to TOTALS.
ChannelMetrics channelMetrics(const ChannelPair& pair, const std::vector<uint8_t>& mask,
                              size_t width, const CompareOptions& options, Totals& totals) {
    ChannelMetrics m;
    m.name = pair.ref->name;
    const size_t block_start = totals.finite.size();
    double channelSum = 0, channelSquares = 0;
    for (size_t i = 0; i < mask.size(); ++i) {
        if (!mask[i]) continue;
        const double d = absoluteDifference(pair.ref->pixels[i], pair.test->pixels[i]);
        if (d > options.fail) totals.flags[i] |= kFailed;
        if (d > options.warn) totals.flags[i] |= kWarned;
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
        totals.finite.push_back(static_cast<float>(d));
    }
    const size_t n = totals.finite.size() - block_start;
    if (n > 0) {
        m.mae = channelSum / static_cast<double>(n);
        m.rmse = std::sqrt(channelSquares / static_cast<double>(n));
    }
    m.p99 = percentile99(totals.finite.begin() + static_cast<std::ptrdiff_t>(block_start),
                         totals.finite.end());
    totals.sum += channelSum;
    totals.sum_squares += channelSquares;
    return m;
}

// The whole image's error, pixel counts and fractions from TOTALS.
void addTotals(Totals& totals, CompareResult& result) {
    if (!totals.finite.empty()) {
        result.mae = totals.sum / static_cast<double>(totals.finite.size());
        result.rmse = std::sqrt(totals.sum_squares / static_cast<double>(totals.finite.size()));
    }
    result.p99 = percentile99(totals.finite.begin(), totals.finite.end());
    for (uint8_t f : totals.flags) {
        result.fail_pixels += (f & kFailed) ? 1 : 0;
        result.warn_pixels += (f & kWarned) ? 1 : 0;
    }
    if (result.pixels > 0) {
        const double n = static_cast<double>(result.pixels);
        result.fail_fraction = static_cast<double>(result.fail_pixels) / n;
        result.warn_fraction = static_cast<double>(result.warn_pixels) / n;
    }
}

// idiff's rule: more failing pixels than allowed, or any difference above hardfail.
Verdict judge(const CompareResult& result, const CompareOptions& options) {
    const double n = static_cast<double>(result.pixels);
    if (static_cast<double>(result.fail_pixels) > options.fail_percent / 100.0 * n ||
        (options.hard_fail && result.max > *options.hard_fail))
        return Verdict::Fail;
    if (static_cast<double>(result.warn_pixels) > options.warn_percent / 100.0 * n)
        return Verdict::Warn;
    return Verdict::Pass;
}

}  // namespace

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

    Totals totals;
    totals.flags.assign(pixels, 0);
    totals.finite.reserve(pixels * pairs.size());
    for (const auto& pair : pairs) {
        ChannelMetrics m = channelMetrics(pair, mask, width, options, totals);
        result.channels.push_back(m.name);
        result.nonfinite += m.nonfinite;
        if (result.per_channel.empty() || m.max > result.max) {
            result.max = m.max;
            result.max_x = m.max_x;
            result.max_y = m.max_y;
            result.max_channel = m.name;
        }
        result.per_channel.push_back(std::move(m));
    }
    addTotals(totals, result);
    shadowRegion(ref, test, mask, result);
    result.verdict = judge(result, options);
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

}  // namespace penumbra::output
