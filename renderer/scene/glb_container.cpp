// GLB container reading and writing: header, chunk lengths and types checked against the file
// size (tinygltf 2.7 can read 8 bytes past a GLB whose BIN chunk length is off).
#include "renderer/scene/glb_container.h"

#include <algorithm>
#include <cstdint>
#include <cstring>

#include "renderer/core/error.h"

namespace penumbra::scene {
namespace {

constexpr std::uint32_t kGlbMagic = 0x46546C67;   // "glTF"
constexpr std::uint32_t kChunkJson = 0x4E4F534A;  // "JSON"
constexpr std::uint32_t kChunkBin = 0x004E4942;   // "BIN\0"

// GLB is little-endian, as is every platform this builds for.
std::uint32_t readU32(const std::string& bytes, std::size_t offset) {
    std::uint32_t v = 0;
    std::memcpy(&v, bytes.data() + offset, 4);
    return v;
}

void appendU32(std::string& out, std::uint32_t v) {
    char b[4];
    std::memcpy(b, &v, 4);
    out.append(b, 4);
}

}  // namespace

bool isGlb(const std::string& bytes) {
    return bytes.size() >= 4 && readU32(bytes, 0) == kGlbMagic;
}

GlbParts splitGlb(const std::string& bytes, const std::string& label) {
    if (bytes.size() < 20) throw InputError(label + ": GLB file too short");
    const std::uint32_t version = readU32(bytes, 4);
    if (version != 2)
        throw InputError(label + ": unsupported GLB version " + std::to_string(version));
    const std::uint32_t length = readU32(bytes, 8);
    if (length > bytes.size())
        throw InputError(label + ": GLB header says " + std::to_string(length) +
                         " bytes but the file has " + std::to_string(bytes.size()) +
                         " (truncated?)");
    GlbParts parts;
    std::size_t offset = 12;
    bool first = true;
    while (offset + 8 <= length) {
        const std::uint64_t chunk_length = readU32(bytes, offset);
        const std::uint32_t type = readU32(bytes, offset + 4);
        if (offset + 8 + chunk_length > length)
            throw InputError(label + ": GLB chunk at byte " + std::to_string(offset) +
                             " runs past the end of the file");
        if (first && type != kChunkJson)
            throw InputError(label + ": GLB does not start with a JSON chunk");
        if (first) {
            parts.json = bytes.substr(offset + 8, chunk_length);
        } else if (type == kChunkBin && !parts.has_bin) {
            parts.bin = bytes.substr(offset + 8, chunk_length);
            parts.has_bin = true;
        }
        first = false;
        offset += 8 + chunk_length;
    }
    if (first) throw InputError(label + ": GLB has no JSON chunk");
    // Exporters pad the JSON chunk with spaces or (wrongly) zero bytes.
    while (!parts.json.empty() && (parts.json.back() == '\0' || parts.json.back() == ' '))
        parts.json.pop_back();
    return parts;
}

std::string assembleGlb(const std::string& json, const GlbParts& parts) {
    std::string json_chunk = json;
    json_chunk.resize((json_chunk.size() + 3) / 4 * 4, ' ');
    std::string bin_chunk = parts.bin;
    if (parts.has_bin)
        bin_chunk.resize(std::max<std::size_t>(4, (bin_chunk.size() + 3) / 4 * 4), '\0');
    const std::size_t total =
        12 + 8 + json_chunk.size() + (parts.has_bin ? 8 + bin_chunk.size() : 0);
    std::string out;
    out.reserve(total);
    appendU32(out, kGlbMagic);
    appendU32(out, 2);
    appendU32(out, static_cast<std::uint32_t>(total));
    appendU32(out, static_cast<std::uint32_t>(json_chunk.size()));
    appendU32(out, kChunkJson);
    out += json_chunk;
    if (parts.has_bin) {
        appendU32(out, static_cast<std::uint32_t>(bin_chunk.size()));
        appendU32(out, kChunkBin);
        out += bin_chunk;
    }
    return out;
}

}  // namespace penumbra::scene
