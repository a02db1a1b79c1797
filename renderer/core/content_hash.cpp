// 64-bit FNV-1a: see content_hash.h.
#include "renderer/core/content_hash.h"

#include <cstdint>
#include <cstdio>
#include <fstream>
#include <vector>

namespace penumbra {
namespace {

constexpr std::uint64_t kOffsetBasis = 14695981039346656037ull;  // 0xcbf29ce484222325

std::uint64_t update(std::uint64_t h, std::string_view bytes) {
    for (unsigned char c : bytes) h = (h ^ c) * 1099511628211ull;
    return h;
}

std::string hex(std::uint64_t h) {
    char buf[17];
    std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
    return buf;
}

}  // namespace

std::string contentHash(std::string_view bytes) {
    return hex(update(kOffsetBasis, bytes));
}

std::string fileContentHash(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return {};
    std::vector<char> block(std::size_t{1} << 20);
    std::uint64_t h = kOffsetBasis;
    while (in) {
        in.read(block.data(), static_cast<std::streamsize>(block.size()));
        h = update(h, std::string_view(block.data(), static_cast<std::size_t>(in.gcount())));
    }
    return in.eof() && !in.bad() ? hex(h) : std::string();
}

}  // namespace penumbra
