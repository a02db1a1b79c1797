// The memory limit: see memory_limit.h.
#include "renderer/core/memory_limit.h"

#include <unistd.h>

#include <atomic>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>

#include "renderer/core/error.h"

namespace penumbra {
namespace {

std::atomic<std::uint64_t> g_limit{0};  // 0: not set, use the default

}  // namespace

std::uint64_t defaultMemoryLimit() {
    const long pages = ::sysconf(_SC_PHYS_PAGES);
    const long page = ::sysconf(_SC_PAGE_SIZE);
    if (pages <= 0 || page <= 0) return std::uint64_t{4} << 30;
    return static_cast<std::uint64_t>(pages) * static_cast<std::uint64_t>(page) / 2;
}

std::uint64_t memoryLimit() {
    const std::uint64_t set = g_limit.load();
    return set ? set : defaultMemoryLimit();
}

void setMemoryLimit(std::uint64_t bytes) {
    g_limit.store(bytes);
}

std::optional<std::uint64_t> parseMemorySize(std::string_view text) {
    double value = 0;
    const char* begin = text.data();
    const char* end = begin + text.size();
    auto [ptr, ec] = std::from_chars(begin, end, value);
    if (text.empty() || ec != std::errc() || !std::isfinite(value) || !(value > 0))
        return std::nullopt;
    std::string_view unit(ptr, static_cast<std::size_t>(end - ptr));
    double scale = 1;
    if (!unit.empty()) {
        const std::string_view units = "KMGT";
        const std::size_t power = units.find(static_cast<char>(unit[0] & ~0x20));
        if (power != std::string_view::npos) {
            scale = std::ldexp(1.0, 10 * static_cast<int>(power + 1));
            unit.remove_prefix(1);
        }
        if (unit != "" && unit != "B" && unit != "iB") return std::nullopt;
    }
    const double bytes = std::floor(value * scale);
    if (bytes < 1 || bytes > std::ldexp(1.0, 60)) return std::nullopt;
    return static_cast<std::uint64_t>(bytes);
}

std::string formatBytes(std::uint64_t bytes) {
    const char* units[] = {"KiB", "MiB", "GiB", "TiB", "PiB", "EiB"};
    if (bytes < 1024) return std::to_string(bytes) + " bytes";
    double v = static_cast<double>(bytes);
    int u = -1;
    while (v >= 1024 && u < 5) {
        v /= 1024;
        ++u;
    }
    char text[32];
    std::snprintf(text, sizeof text, v < 10 ? "%.1f %s" : "%.0f %s", v, units[u]);
    return text;
}

void requireMemory(std::uint64_t bytes, const std::string& where, const std::string& what) {
    const std::uint64_t limit = memoryLimit();
    if (bytes <= limit) return;
    throw InputError(where + ": " + what + " needs about " + formatBytes(bytes) +
                     ", more than the memory limit of " + formatBytes(limit) + " (--memory-limit)");
}

std::uint64_t saturatingProduct(std::initializer_list<std::uint64_t> factors) {
    std::uint64_t out = 1;
    for (std::uint64_t f : factors) {
        if (f != 0 && out > std::numeric_limits<std::uint64_t>::max() / f)
            return std::numeric_limits<std::uint64_t>::max();
        out *= f;
    }
    return out;
}

}  // namespace penumbra
