// The OpenEXR header walk: see exr_header.h. The layout is that of the OpenEXR file format
// (magic, version with its flags, then NUL-terminated name, type, little-endian int32 size).
#include "renderer/core/exr_header.h"

#include <sstream>
#include <string_view>

namespace penumbra {

namespace {

constexpr std::size_t kMaxName = 255;           // the long-names limit; short names are 31
constexpr unsigned char kMultiPartFlag = 0x10;  // bit 12 of the version field

// Reads a NUL-terminated name into NAME; false when the file ends first or it is too long.
bool readName(std::istream& in, std::string& name) {
    name.clear();
    for (char c; in.get(c);) {
        if (c == '\0') return true;
        if (name.size() == kMaxName) return false;
        name.push_back(c);
    }
    return false;
}

}  // namespace

std::string exrHeaderProblem(std::istream& in, std::uintmax_t size) {
    char version[8];  // magic and version
    if (!in.read(version, 8) || std::string_view(version, 4) != "\x76\x2f\x31\x01")
        return "";  // not OpenEXR: the decoder says so in its own words
    const bool multiPart = (static_cast<unsigned char>(version[5]) & kMultiPartFlag) != 0;
    std::string name, type;
    // A header ends with an empty name; a multi-part file's list of headers with an empty header.
    for (bool firstOfHeader = true;;) {
        if (!readName(in, name)) return "truncated header or attribute name too long";
        if (name.empty()) {
            if (!multiPart || firstOfHeader) return "";
            firstOfHeader = true;
            continue;
        }
        firstOfHeader = false;
        unsigned char le[4];
        if (!readName(in, type) || !in.read(reinterpret_cast<char*>(le), 4))
            return "truncated header at attribute '" + name + "'";
        const auto bytes = static_cast<std::int32_t>(le[0] | le[1] << 8 | le[2] << 16 |
                                                     static_cast<std::uint32_t>(le[3]) << 24);
        const std::streamoff position = in.tellg();
        const auto at = static_cast<std::uintmax_t>(position);
        if (position < 0 || at > size || bytes < 0 ||
            static_cast<std::uintmax_t>(bytes) > size - at)
            return "header attribute '" + name + "' declares " + std::to_string(bytes) +
                   " bytes, beyond the file's " + std::to_string(size) + " bytes";
        in.seekg(bytes, std::ios::cur);
    }
}

std::string exrHeaderProblem(const unsigned char* bytes, std::size_t size) {
    std::istringstream in(std::string(reinterpret_cast<const char*>(bytes), size));
    return exrHeaderProblem(in, size);
}

}  // namespace penumbra
