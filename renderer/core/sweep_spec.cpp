// Sweep axes and their product: see sweep_spec.h.
#include "renderer/core/sweep_spec.h"

#include <charconv>
#include <cmath>
#include <set>

#include "renderer/core/error.h"
#include "renderer/core/json_bounds.h"

namespace penumbra {
namespace {

constexpr long kMaxAxisValues = 10000;

bool parseNumber(std::string_view s, double& out) {
    if (s.empty()) return false;
    auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
    return ec == std::errc() && ptr == s.data() + s.size() && std::isfinite(out);
}

// Splits on commas outside brackets, braces and quotes.
std::vector<std::string_view> splitTopLevel(std::string_view s) {
    std::vector<std::string_view> parts;
    int depth = 0;
    bool quoted = false;
    size_t start = 0;
    for (size_t i = 0; i < s.size(); ++i) {
        char c = s[i];
        if (quoted) {
            if (c == '\\')
                ++i;
            else if (c == '"')
                quoted = false;
        } else if (c == '"') {
            quoted = true;
        } else if (c == '[' || c == '{') {
            ++depth;
        } else if (c == ']' || c == '}') {
            --depth;
        } else if (c == ',' && depth == 0) {
            parts.push_back(s.substr(start, i - start));
            start = i + 1;
        }
    }
    parts.push_back(s.substr(start));
    return parts;
}

nlohmann::json parseValue(std::string_view text, const std::string& where) {
    if (text.empty()) throw InputError(where + ": empty value");
    if (auto v = parseJsonBounded(text, where)) return std::move(*v);
    const char first = text.front();
    if (first == '[' || first == '{' || first == '"')
        throw InputError(where + ": '" + quoteText(text) + "' is not valid JSON");
    return std::string(text);  // a bare word
}

// A:B:N or A:B:N:log, or false when TEXT is not of that form.
bool parseRange(std::string_view text, const std::string& where, VaryAxis& axis) {
    std::vector<std::string_view> f;
    size_t start = 0;
    for (size_t i = 0; i <= text.size(); ++i)
        if (i == text.size() || text[i] == ':') {
            f.push_back(text.substr(start, i - start));
            start = i + 1;
        }
    if (f.size() != 3 && f.size() != 4) return false;
    double a = 0, b = 0, n = 0;
    if (!parseNumber(f[0], a) || !parseNumber(f[1], b) || !parseNumber(f[2], n)) {
        if (text.find(',') == std::string_view::npos && text.front() != '"' && text.front() != '[')
            throw InputError(where + ": a range is A:B:N or A:B:N:log with numbers A, B, N");
        return false;
    }
    if (f.size() == 4 && f[3] != "log")
        throw InputError(where + ": the fourth part of a range must be 'log'");
    if (n != std::floor(n) || n < 1 || n > kMaxAxisValues)
        throw InputError(where + ": N must be a whole number from 1 to " +
                         std::to_string(kMaxAxisValues));
    axis.log_scale = f.size() == 4;
    if (axis.log_scale && (a <= 0 || b <= 0))
        throw InputError(where + ": a log range needs A and B above 0");
    const int count = static_cast<int>(n);
    // Whole end points with whole steps stay integers (so integer parameters can be swept).
    const bool integral = !axis.log_scale && a == std::floor(a) && b == std::floor(b) &&
                          std::fabs(a) < 1e15 && std::fabs(b) < 1e15 &&
                          (count == 1 || std::fmod(b - a, count - 1) == 0);
    for (int i = 0; i < count; ++i) {
        double t = count == 1 ? 0.0 : static_cast<double>(i) / (count - 1);
        double v = axis.log_scale ? a * std::pow(b / a, t) : a + (b - a) * t;
        if (i == count - 1 && count > 1) v = b;  // exact end point
        axis.values.push_back(integral ? nlohmann::json(std::llround(v)) : nlohmann::json(v));
    }
    return true;
}

}  // namespace

VaryAxis parseVary(std::string_view text) {
    const std::string where = "--vary " + quoteText(text);
    size_t eq = text.find('=');
    if (eq == std::string_view::npos || eq == 0)
        throw InputError(where + ": expected KEY=V1,V2,... or KEY=A:B:N[:log]");
    VaryAxis axis;
    axis.key = std::string(text.substr(0, eq));
    std::string_view rest = text.substr(eq + 1);
    if (rest.empty()) throw InputError(where + ": no values");
    if (parseRange(rest, where, axis)) return axis;
    for (std::string_view part : splitTopLevel(rest)) {
        axis.values.push_back(parseValue(part, where));
        if (axis.values.size() > static_cast<size_t>(kMaxAxisValues))
            throw InputError(where + ": more than " + std::to_string(kMaxAxisValues) + " values");
    }
    return axis;
}

std::vector<SweepPoint> cartesianProduct(const std::vector<VaryAxis>& axes, size_t max_points) {
    std::set<std::string> keys;
    size_t total = 1;
    for (const auto& a : axes) {
        if (!keys.insert(a.key).second)
            throw InputError("--vary " + a.key + ": the key is varied twice");
        if (a.values.empty()) throw InputError("--vary " + a.key + ": no values");
        total *= a.values.size();
        if (total > max_points)
            throw InputError("--vary: more than " + std::to_string(max_points) + " combinations");
    }
    std::vector<SweepPoint> points;
    std::vector<size_t> index(axes.size(), 0);
    for (size_t n = 0; n < total; ++n) {
        SweepPoint p;
        for (size_t a = 0; a < axes.size(); ++a)
            p.emplace_back(axes[a].key, axes[a].values[index[a]]);
        points.push_back(std::move(p));
        for (size_t a = axes.size(); a-- > 0;) {
            if (++index[a] < axes[a].values.size()) break;
            index[a] = 0;
        }
    }
    return points;
}

}  // namespace penumbra
