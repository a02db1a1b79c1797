// Blender-style frame specs: comma-separated items, each N, A-B or A-B:STEP.
#include "renderer/core/frame_spec.h"

#include <algorithm>
#include <charconv>
#include <set>

#include "renderer/core/error.h"

namespace penumbra {
namespace {

constexpr long kMaxFrame = 10'000'000;    // frame numbers beyond this are surely typos
constexpr size_t kMaxFrames = 1'000'000;  // a list longer than this is refused before allocation

std::string_view trim(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
    return s;
}

long parseNumber(std::string_view text, std::string_view item, std::string_view where) {
    text = trim(text);
    long value = 0;
    const char* first = text.data();
    const char* last = text.data() + text.size();
    if (!text.empty() && text.front() == '+') ++first;
    auto [ptr, ec] = std::from_chars(first, last, value);
    if (text.empty() || ec != std::errc() || ptr != last)
        throw InputError(std::string(where) + ": '" + std::string(item) +
                         "' is not a frame, range A-B or range A-B:STEP");
    if (value < -kMaxFrame || value > kMaxFrame)
        throw InputError(std::string(where) + ": frame " + std::to_string(value) +
                         " is out of range (at most " + std::to_string(kMaxFrame) + ")");
    return value;
}

}  // namespace

std::vector<int> parseFrameSpec(std::string_view spec, std::string_view where) {
    std::set<int> frames;
    if (trim(spec).empty()) throw InputError(std::string(where) + ": empty frame spec");
    size_t start = 0;
    while (start <= spec.size()) {
        size_t comma = spec.find(',', start);
        if (comma == std::string_view::npos) comma = spec.size();
        std::string_view item = trim(spec.substr(start, comma - start));
        if (item.empty())
            throw InputError(std::string(where) + ": empty item in frame spec '" +
                             std::string(spec) + "'");
        std::string_view range = item;
        long step = 1;
        if (size_t colon = item.find(':'); colon != std::string_view::npos) {
            range = item.substr(0, colon);
            step = parseNumber(item.substr(colon + 1), item, where);
            if (step <= 0)
                throw InputError(std::string(where) + ": step in '" + std::string(item) +
                                 "' must be positive");
        }
        // A dash after the first character separates a range (the first may be a minus sign).
        size_t dash = range.find('-', 1);
        long first = 0, last = 0;
        if (dash == std::string_view::npos) {
            if (range.size() != item.size())
                throw InputError(std::string(where) + ": '" + std::string(item) +
                                 "' has a step but no range");
            first = last = parseNumber(range, item, where);
        } else {
            first = parseNumber(range.substr(0, dash), item, where);
            last = parseNumber(range.substr(dash + 1), item, where);
            if (last < first)
                throw InputError(std::string(where) + ": range '" + std::string(item) +
                                 "' is empty (end before start)");
        }
        for (long f = first; f <= last; f += step) {
            frames.insert(static_cast<int>(f));
            if (frames.size() > kMaxFrames)
                throw InputError(std::string(where) + ": more than " + std::to_string(kMaxFrames) +
                                 " frames");
        }
        start = comma + 1;
    }
    return {frames.begin(), frames.end()};
}

}  // namespace penumbra
