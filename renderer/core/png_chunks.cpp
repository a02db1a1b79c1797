// PNG chunk lengths against the file's size: see png_chunks.h.
#include "renderer/core/png_chunks.h"

#include <string_view>

namespace penumbra {

std::string pngChunkProblem(std::istream& in, std::uintmax_t size) {
    char signature[8];
    if (!in.read(signature, 8) || std::string_view(signature, 8) != "\x89PNG\r\n\x1a\n")
        return "";  // not PNG: the decoder says so in its own words
    std::uintmax_t at = 8;
    for (;;) {
        unsigned char header[8];  // length (big-endian), type
        if (!in.read(reinterpret_cast<char*>(header), 8)) return "";
        at += 8;
        const std::uint32_t length = static_cast<std::uint32_t>(header[0]) << 24 |
                                     static_cast<std::uint32_t>(header[1]) << 16 |
                                     static_cast<std::uint32_t>(header[2]) << 8 | header[3];
        const std::string type(reinterpret_cast<const char*>(header + 4), 4);
        // The data and its 4-byte CRC must lie in the file.
        if (length > 0x7fffffffu || at > size || std::uintmax_t{length} + 4 > size - at)
            return "chunk '" + type + "' declares " + std::to_string(length) +
                   " bytes, beyond the file's " + std::to_string(size) + " bytes";
        if (type == "IEND") return "";
        at += std::uintmax_t{length} + 4;
        if (!in.seekg(static_cast<std::streamoff>(at))) return "";
    }
}

}  // namespace penumbra
