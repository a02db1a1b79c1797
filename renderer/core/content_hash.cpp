// 64-bit FNV-1a: see content_hash.h.
#include "renderer/core/content_hash.h"

#include <cstdint>
#include <cstdio>

namespace penumbra {

std::string contentHash(std::string_view bytes) {
    std::uint64_t h = 1469598103934665603ull;
    for (unsigned char c : bytes) h = (h ^ c) * 1099511628211ull;
    char buf[17];
    std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
    return buf;
}

}  // namespace penumbra
