// The program binary cache: see program_cache.h. A file holds a header line, the binary's
// format, the key's and the binary's sizes, the binary's hash, the key itself (compared whole,
// so a hash collision cannot load another program) and the binary.
#include "renderer/gl/program_cache.h"

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <vector>

#include "renderer/core/atomic_file.h"
#include "renderer/core/content_hash.h"
#include "renderer/gl/context.h"

namespace penumbra::gl {
namespace {

constexpr std::string_view kMagic = "penumbra-program-binary 1\n";
std::atomic<int> g_compiled{0}, g_from_cache{0};

struct Header {  // trivial, so it is zeroed whole (padding too) before it is filled
    std::uint64_t key_size, binary_size;
    std::uint32_t format;
    char binary_hash[16];
};

// The driver's strings and KEY: what a binary depends on.
std::string fullKey(const std::string& key) {
    return glString(GL_VENDOR) + '\0' + glString(GL_RENDERER) + '\0' + glString(GL_VERSION) + '\0' +
           key;
}

// The driver can hand out and take back binaries.
bool driverHasBinaries() {
    GLint formats = 0;
    glGetIntegerv(GL_NUM_PROGRAM_BINARY_FORMATS, &formats);
    return formats > 0;
}

bool formatSupported(GLenum format) {
    GLint count = 0;
    glGetIntegerv(GL_NUM_PROGRAM_BINARY_FORMATS, &count);
    if (count <= 0) return false;
    std::vector<GLint> formats(static_cast<size_t>(count));
    glGetIntegerv(GL_PROGRAM_BINARY_FORMATS, formats.data());
    for (GLint f : formats)
        if (static_cast<GLenum>(f) == format) return true;
    return false;
}

std::filesystem::path fileFor(const std::string& full_key) {
    const std::filesystem::path folder = programCacheFolder();
    return folder.empty() ? folder : folder / (contentHash(full_key) + ".bin");
}

}  // namespace

ProgramCacheStats programCacheStats() {
    return {g_compiled.load(), g_from_cache.load()};
}

void countCompiledProgram() {
    ++g_compiled;
}

std::filesystem::path userCacheFolder() {
    // XDG Base Directory: a relative $XDG_CACHE_HOME is ignored.
    if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg == '/')
        return std::filesystem::path(xdg);
    if (const char* home = std::getenv("HOME"); home && *home == '/')
        return std::filesystem::path(home) / ".cache";
    return {};
}

std::filesystem::path programCacheFolder() {
    if (const char* off = std::getenv("PENUMBRA_PROGRAM_CACHE"); off && std::strcmp(off, "0") == 0)
        return {};
    const std::filesystem::path user = userCacheFolder();
    return user.empty() ? user : user / "penumbra" / "programs";
}

void createProgramCacheFolder() {
    // With the program cache off, the user's cache folder alone: Mesa's cache goes in it.
    std::filesystem::path folder = programCacheFolder();
    if (folder.empty()) folder = userCacheFolder();
    std::error_code error;
    if (!folder.empty()) std::filesystem::create_directories(folder, error);
}

bool loadCachedProgram(GLuint program, const std::string& key) {
    const std::string full = fullKey(key);
    const std::filesystem::path file = fileFor(full);
    if (file.empty()) return false;
    std::ifstream in(file, std::ios::binary);
    std::string magic(kMagic.size(), '\0');
    Header h{};
    if (!in.read(magic.data(), static_cast<std::streamsize>(magic.size())) || magic != kMagic ||
        !in.read(reinterpret_cast<char*>(&h), sizeof h) || h.key_size != full.size() ||
        h.binary_size == 0 || h.binary_size > (std::uint64_t{1} << 30))
        return false;
    std::string stored_key(full.size(), '\0');
    std::string binary(h.binary_size, '\0');
    if (!in.read(stored_key.data(), static_cast<std::streamsize>(stored_key.size())) ||
        stored_key != full ||
        !in.read(binary.data(), static_cast<std::streamsize>(binary.size())) ||
        in.peek() != std::char_traits<char>::eof() ||
        contentHash(binary) != std::string_view(h.binary_hash, sizeof h.binary_hash) ||
        !formatSupported(h.format))
        return false;
    glProgramBinary(program, h.format, binary.data(), static_cast<GLsizei>(binary.size()));
    GLint ok = 0;
    glGetProgramiv(program, GL_LINK_STATUS, &ok);
    if (ok) ++g_from_cache;
    return ok != 0;
}

void storeCachedProgram(GLuint program, const std::string& key) {
    const std::string full = fullKey(key);
    const std::filesystem::path file = fileFor(full);
    if (file.empty() || !driverHasBinaries()) return;
    GLint length = 0;
    glGetProgramiv(program, GL_PROGRAM_BINARY_LENGTH, &length);
    if (length <= 0) return;
    std::string binary(static_cast<size_t>(length), '\0');
    GLenum format = 0;
    GLsizei written = 0;
    glGetProgramBinary(program, length, &written, &format, binary.data());
    if (written <= 0) return;
    binary.resize(static_cast<size_t>(written));
    Header h;
    std::memset(&h, 0, sizeof h);  // padding too: the file's bytes are all defined
    h.format = format;
    h.key_size = full.size();
    h.binary_size = binary.size();
    const std::string hash = contentHash(binary);
    std::memcpy(h.binary_hash, hash.data(), std::min(hash.size(), sizeof h.binary_hash));
    std::string bytes(kMagic);
    bytes.append(reinterpret_cast<const char*>(&h), sizeof h);
    bytes += full;
    bytes += binary;
    try {
        writeFileAtomically(file, bytes);
    } catch (const std::exception&) {
        // A cache that cannot be written only costs the next process a compile.
    }
}

}  // namespace penumbra::gl
