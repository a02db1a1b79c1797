// Atomic writes: see atomic_file.h.
#include "renderer/core/atomic_file.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>

#include "renderer/core/error.h"
#include "renderer/core/regular_file.h"

namespace penumbra {
namespace {
constexpr const char* kOnlyRegular = " (an output replaces only a regular file)";
}  // namespace

std::filesystem::path temporaryPathFor(const std::filesystem::path& path) {
    std::filesystem::path dir = path.parent_path();
    std::string name = ".";
    name += path.filename().string();
    name += ".";
    name += std::to_string(::getpid());
    name += ".tmp";
    return dir.empty() ? std::filesystem::path(name) : dir / name;
}

void writeAtomically(const std::filesystem::path& path,
                     const std::function<void(const std::filesystem::path&)>& write) {
    std::error_code ec;
    if (path.has_parent_path()) {
        std::filesystem::create_directories(path.parent_path(), ec);
        if (ec)
            throw RuntimeError(path.parent_path().string() +
                               ": cannot create folder: " + ec.message());
    }
    // rename() replaces whatever is at PATH: a device node, a FIFO, a link, an empty folder.
    if (const std::string why = notReplaceableReason(path); !why.empty())
        throw RuntimeError(path.string() + ": " + why + kOnlyRegular);
    const std::filesystem::path tmp = temporaryPathFor(path);
    try {
        write(tmp);
    } catch (const Error&) {
        std::filesystem::remove(tmp, ec);
        throw;
    } catch (const std::exception& e) {
        std::filesystem::remove(tmp, ec);
        throw RuntimeError(path.string() + ": write failed: " + e.what());
    }
    std::filesystem::rename(tmp, path, ec);
    if (ec) {
        const std::string why = ec.message();  // before remove() overwrites EC
        std::filesystem::remove(tmp, ec);
        throw RuntimeError(path.string() + ": cannot rename into place: " + why);
    }
}

void checkOutputPath(const std::filesystem::path& path, const std::string& label) {
    if (const std::string why = notReplaceableReason(path); !why.empty())
        throw InputError(label + ": " + path.string() + ": " + why + kOnlyRegular);
}

void writeFileAtomically(const std::filesystem::path& path, const std::string& text) {
    writeAtomically(path, [&](const std::filesystem::path& tmp) {
        std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
        out.write(text.data(), static_cast<std::streamsize>(text.size()));
        out.close();
        if (!out) throw RuntimeError(tmp.string() + ": " + std::strerror(errno));
    });
}

}  // namespace penumbra
