// Cryptomatte: see cryptomatte.h. One rank per pixel is exact at one visibility sample per
// pixel: the id channel holds one object per pixel.
#include "renderer/output/cryptomatte.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <set>

#include <nlohmann/json.hpp>

namespace penumbra::output {

namespace {

uint32_t rotl32(uint32_t x, int r) {
    return (x << r) | (x >> (32 - r));
}

std::string hexHash(uint32_t hash) {
    char buf[9];
    std::snprintf(buf, sizeof buf, "%08x", hash);
    return buf;
}

}  // namespace

uint32_t murmurHash3(std::string_view key, uint32_t seed) {
    const auto* data = reinterpret_cast<const unsigned char*>(key.data());
    const size_t len = key.size();
    const size_t blocks = len / 4;
    constexpr uint32_t c1 = 0xcc9e2d51, c2 = 0x1b873593;
    uint32_t h1 = seed;
    for (size_t i = 0; i < blocks; ++i) {
        uint32_t k1 = uint32_t{data[4 * i]} | uint32_t{data[4 * i + 1]} << 8 |
                      uint32_t{data[4 * i + 2]} << 16 | uint32_t{data[4 * i + 3]} << 24;
        k1 *= c1;
        k1 = rotl32(k1, 15);
        k1 *= c2;
        h1 ^= k1;
        h1 = rotl32(h1, 13);
        h1 = h1 * 5 + 0xe6546b64;
    }
    const unsigned char* tail = data + 4 * blocks;
    uint32_t k1 = 0;
    switch (len & 3) {
        case 3:
            k1 ^= uint32_t{tail[2]} << 16;
            [[fallthrough]];
        case 2:
            k1 ^= uint32_t{tail[1]} << 8;
            [[fallthrough]];
        case 1:
            k1 ^= tail[0];
            k1 *= c1;
            k1 = rotl32(k1, 15);
            k1 *= c2;
            h1 ^= k1;
    }
    h1 ^= static_cast<uint32_t>(len);
    h1 ^= h1 >> 16;
    h1 *= 0x85ebca6b;
    h1 ^= h1 >> 13;
    h1 *= 0xc2b2ae35;
    h1 ^= h1 >> 16;
    return h1;
}

float cryptomatteId(uint32_t hash) {
    const uint32_t mantissa = hash & ((1u << 23) - 1);
    const uint32_t exponent = std::clamp((hash >> 23) & 0xffu, 1u, 254u);
    const uint32_t bits = (hash & 0x80000000u) | (exponent << 23) | mantissa;
    float f;
    std::memcpy(&f, &bits, sizeof f);
    return f;
}

std::string cryptomatteManifest(const std::vector<std::string>& names) {
    nlohmann::json manifest = nlohmann::json::object();
    for (const auto& name : names) manifest[name] = hexHash(murmurHash3(name));
    return manifest.dump();
}

void addCryptomatte(Image& image, const std::string& layer, const std::vector<std::string>& names,
                    int samples) {
    std::vector<float> ids(names.size());
    for (size_t i = 0; i < names.size(); ++i) ids[i] = cryptomatteId(murmurHash3(names[i]));
    const size_t n = static_cast<size_t>(image.width) * static_cast<size_t>(image.height);
    image.channels.reserve(image.channels.size() + 4);  // no add() below moves a channel
    const ImageChannel* id = image.find("id");
    const ImageChannel* alpha = samples > 1 ? image.find("A") : nullptr;
    auto& rank = image.add(layer + "00.R", PixelType::Float).pixels;
    auto& coverage = image.add(layer + "00.G", PixelType::Float).pixels;
    image.add(layer + "00.B", PixelType::Float);
    image.add(layer + "00.A", PixelType::Float);
    for (size_t i = 0; id && i < n; ++i) {
        const float v = id->pixels[i];
        if (!(v >= 0.0f) || v >= static_cast<float>(names.size())) continue;  // background
        rank[i] = ids[static_cast<size_t>(v + 0.5f)];  // an index: no lround call a pixel
        coverage[i] = alpha ? alpha->pixels[i] : 1.0f;
    }
    const std::string prefix = "cryptomatte/" + hexHash(murmurHash3(layer)).substr(0, 7) + "/";
    image.attributes.emplace_back(prefix + "name", layer);
    image.attributes.emplace_back(prefix + "hash", "MurmurHash3_32");
    image.attributes.emplace_back(prefix + "conversion", "uint32_to_float32");
    image.attributes.emplace_back(prefix + "manifest", cryptomatteManifest(names));
}

}  // namespace penumbra::output
