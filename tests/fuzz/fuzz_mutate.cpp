// Mutations: see fuzz_mutate.h.
#include "tests/fuzz/fuzz_mutate.h"

#include <algorithm>
#include <cctype>
#include <cstring>
#include <string>

namespace penumbra::fuzz {
namespace {

constexpr std::size_t kMaxInput = std::size_t{2} << 20;

const std::uint32_t kInteresting[] = {
    0,       1,     0x7f,  0x80,     0xff,       0x100,      0x7fff,     0x8000,    0xffff,
    0x10000, 16384, 16385, 60000000, 0x7fffffff, 0x80000000, 0xffffffff, 0xfffffffe};
const char* const kNumbers[] = {
    "1e39",     "-1e39",      "-1",    "0",   "0.5", "16384", "16385",
    "60000000", "4294967296", "1e308", "-0",  "NaN", "1e-45", "99999999999999999999",
    "[",        "{",          "\"\"",  "null"};

std::size_t pick(std::mt19937_64& rng, std::size_t n) {
    return n ? rng() % n : 0;
}

// Replaces a run of digits in a text-looking input with one of kNumbers.
bool replaceNumber(Bytes& b, std::mt19937_64& rng) {
    std::vector<std::size_t> starts;
    for (std::size_t i = 0; i < b.size(); ++i)
        if (std::isdigit(b[i]) && (i == 0 || !std::isdigit(b[i - 1]))) starts.push_back(i);
    if (starts.empty()) return false;
    const std::size_t s = starts[pick(rng, starts.size())];
    std::size_t e = s;
    while (e < b.size() && (std::isdigit(b[e]) || b[e] == '.' || b[e] == 'e' || b[e] == '-')) ++e;
    const char* n = kNumbers[pick(rng, std::size(kNumbers))];
    b.erase(b.begin() + static_cast<long>(s), b.begin() + static_cast<long>(e));
    b.insert(b.begin() + static_cast<long>(s), n, n + std::strlen(n));
    return true;
}

void mutateOnce(Bytes& b, const std::vector<Bytes>& pool, std::mt19937_64& rng) {
    switch (pick(rng, 10)) {
        case 0:  // flip a bit
            if (!b.empty()) b[pick(rng, b.size())] ^= static_cast<std::uint8_t>(1u << pick(rng, 8));
            break;
        case 1:  // a random byte
            if (!b.empty()) b[pick(rng, b.size())] = static_cast<std::uint8_t>(rng());
            break;
        case 2: {  // an interesting 32-bit integer, either byte order
            if (b.size() < 4) break;
            std::uint32_t v = kInteresting[pick(rng, std::size(kInteresting))];
            if (rng() & 1) v = __builtin_bswap32(v);
            std::memcpy(b.data() + pick(rng, b.size() - 3), &v, 4);
            break;
        }
        case 3:  // truncate
            b.resize(pick(rng, b.size() + 1));
            break;
        case 4: {  // delete a chunk
            if (b.empty()) break;
            const std::size_t at = pick(rng, b.size());
            const std::size_t n = 1 + pick(rng, std::min<std::size_t>(b.size() - at, 256));
            b.erase(b.begin() + static_cast<long>(at), b.begin() + static_cast<long>(at + n));
            break;
        }
        case 5: {  // duplicate a chunk
            if (b.empty() || b.size() > kMaxInput / 2) break;
            const std::size_t at = pick(rng, b.size());
            const std::size_t n = 1 + pick(rng, std::min<std::size_t>(b.size() - at, 256));
            const Bytes chunk(b.begin() + static_cast<long>(at),
                              b.begin() + static_cast<long>(at + n));
            b.insert(b.begin() + static_cast<long>(pick(rng, b.size() + 1)), chunk.begin(),
                     chunk.end());
            break;
        }
        case 6: {  // splice: this one's head, another seed's tail
            const Bytes& other = pool[pick(rng, pool.size())];
            if (other.empty()) break;
            b.resize(pick(rng, b.size() + 1));
            const std::size_t from = pick(rng, other.size());
            b.insert(b.end(), other.begin() + static_cast<long>(from), other.end());
            break;
        }
        case 7:
        case 8:  // a number in text replaced
            if (!replaceNumber(b, rng) && !b.empty()) b[pick(rng, b.size())] = '9';
            break;
        default: {  // insert random bytes
            const std::size_t n = 1 + pick(rng, 16);
            const std::size_t at = pick(rng, b.size() + 1);
            for (std::size_t i = 0; i < n; ++i)
                b.insert(b.begin() + static_cast<long>(at), static_cast<std::uint8_t>(rng()));
            break;
        }
    }
    if (b.size() > kMaxInput) b.resize(kMaxInput);
}

}  // namespace

Bytes mutate(const Bytes& seed, const std::vector<Bytes>& pool, std::mt19937_64& rng) {
    Bytes b = seed;
    const std::size_t n = 1 + pick(rng, 4);
    for (std::size_t i = 0; i < n; ++i) mutateOnce(b, pool, rng);
    return b;
}

}  // namespace penumbra::fuzz
