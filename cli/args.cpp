// Hand-written argument cursor: see args.h.
#include "cli/args.h"

#include <algorithm>
#include <charconv>
#include <cmath>

#include "renderer/core/did_you_mean.h"
#include "renderer/core/error.h"
#include "renderer/core/json_bounds.h"
#include "renderer/core/memory_limit.h"

namespace penumbra::cli {

void ArgCursor::noteName(std::string_view short_name, std::string_view long_name) {
    for (std::string_view n : {short_name, long_name})
        if (!n.empty() && std::find(names_.begin(), names_.end(), n) == names_.end())
            names_.emplace_back(n);
}

bool ArgCursor::flag(std::string_view short_name, std::string_view long_name) {
    noteName(short_name, long_name);
    if (done()) return false;
    const std::string& a = args_[index_];
    if ((!short_name.empty() && a == short_name) || a == long_name) {
        ++index_;
        return true;
    }
    if (a.size() > long_name.size() && a.compare(0, long_name.size(), long_name) == 0 &&
        a[long_name.size()] == '=')
        fail(std::string(long_name) + " takes no value");
    return false;
}

std::optional<std::string> ArgCursor::option(std::string_view short_name,
                                             std::string_view long_name) {
    noteName(short_name, long_name);
    if (done()) return std::nullopt;
    const std::string& a = args_[index_];
    if ((!short_name.empty() && a == short_name) || a == long_name) {
        if (index_ + 1 >= args_.size()) fail(a + " needs a value");
        index_ += 2;
        return args_[index_ - 1];
    }
    // "-f1-3": a one-letter option with its value attached.
    if (short_name.size() == 2 && a.size() > 2 && a[1] != '-' &&
        a.compare(0, short_name.size(), short_name) == 0) {
        ++index_;
        return a.substr(short_name.size());
    }
    if (a.size() > long_name.size() && a.compare(0, long_name.size(), long_name) == 0 &&
        a[long_name.size()] == '=') {
        ++index_;
        return a.substr(long_name.size() + 1);
    }
    return std::nullopt;
}

std::optional<std::string> ArgCursor::positional() {
    if (done()) return std::nullopt;
    const std::string& a = args_[index_];
    if (a.size() > 1 && a[0] == '-') return std::nullopt;
    ++index_;
    return a;
}

void ArgCursor::unknown() const {
    const std::string& a = args_[index_];
    if (a == kListFlagsArgument) throw KnownFlags{names_};
    if (a.size() > 1 && a[0] == '-') {
        const std::string typed = a.substr(0, a.find('='));
        const std::string near = nearestName(typed, names_);
        fail("unknown flag '" + quoteText(a) + "' (" +
             (near.empty() ? "" : "did you mean " + near + "? ") + "see --help)");
    }
    fail("unexpected argument '" + quoteText(a) + "' (see --help)");
}

void ArgCursor::fail(const std::string& message) const {
    throw InputError(command_ + ": " + message);
}

double parseDouble(const ArgCursor& c, std::string_view flag, const std::string& text) {
    double v = 0;
    const char* end = text.data() + text.size();
    auto [ptr, ec] = std::from_chars(text.data(), end, v);
    if (text.empty() || ec != std::errc() || ptr != end || !std::isfinite(v))
        c.fail(std::string(flag) + ": expected a number, got '" + quoteText(text) + "'");
    return v;
}

int parseInt(const ArgCursor& c, std::string_view flag, const std::string& text, int min, int max) {
    long v = 0;
    const char* end = text.data() + text.size();
    auto [ptr, ec] = std::from_chars(text.data(), end, v);
    if (text.empty() || ec != std::errc() || ptr != end)
        c.fail(std::string(flag) + ": expected a whole number, got '" + quoteText(text) + "'");
    if (v < min || v > max)
        c.fail(std::string(flag) + ": " + quoteText(text) + " is out of range [" +
               std::to_string(min) + ", " + std::to_string(max) + "]");
    return static_cast<int>(v);
}

std::pair<int, int> parseSize(const ArgCursor& c, std::string_view flag, const std::string& text) {
    size_t x = text.find('x');
    if (x == std::string::npos)
        c.fail(std::string(flag) + ": expected WxH, got '" + quoteText(text) + "'");
    int w = parseInt(c, flag, text.substr(0, x), 1, 1 << 20);
    int h = parseInt(c, flag, text.substr(x + 1), 1, 1 << 20);
    return {w, h};
}

bool parseMemoryLimitFlag(ArgCursor& c) {
    const auto v = c.option("", "--memory-limit");
    if (!v) return false;
    const auto bytes = parseMemorySize(*v);
    if (!bytes)
        c.fail("--memory-limit: expected a size such as 8G or 512M, got '" + quoteText(*v) + "'");
    setMemoryLimit(*bytes);
    return true;
}

}  // namespace penumbra::cli
