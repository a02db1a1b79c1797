// Atomic writes: see atomic_file.h.
#include "renderer/core/atomic_file.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>

#include "renderer/core/error.h"

namespace penumbra {

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
        std::filesystem::remove(tmp, ec);
        throw RuntimeError(path.string() + ": cannot rename into place: " + ec.message());
    }
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
