// Loading the OpenImageIO module: see oiio_module.h. OpenImageIO pulls in about 260 shared
// libraries whose loading cost every process a quarter of a second; only this dlopen pays it.
#include "renderer/core/oiio_module.h"

#include <dlfcn.h>

#include <filesystem>
#include <mutex>
#include <string>
#include <vector>

#include "penumbra/oiio_interface.h"
#include "renderer/core/error.h"

#ifndef PENUMBRA_INSTALL_LIBDIR
#define PENUMBRA_INSTALL_LIBDIR "lib"
#endif

namespace penumbra {
namespace {

namespace fs = std::filesystem;

constexpr const char* kModuleFile = "libpenumbra_oiio.so";
constexpr const char* kEntry = "penumbra_oiio_module";
using Entry = OiioModule* (*)(const char* interface);

// Where the module may lie: beside the executable (the build tree), then in the installed
// library folder (<prefix>/bin/penumbra -> <prefix>/<libdir>/penumbra/).
std::vector<fs::path> candidates() {
    std::error_code ec;
    const fs::path self = fs::read_symlink("/proc/self/exe", ec);
    if (ec) return {};
    const fs::path dir = self.parent_path();
    return {dir / kModuleFile,
            dir.parent_path() / PENUMBRA_INSTALL_LIBDIR / "penumbra" / kModuleFile};
}

OiioModule* fromEntry(void* symbol, const std::string& where) {
    OiioModule* module = reinterpret_cast<Entry>(symbol)(PENUMBRA_OIIO_INTERFACE);
    if (!module)
        throw RuntimeError("cannot load the OpenImageIO module " + where +
                           ": built from another revision of its interface than this binary "
                           "(rebuild or reinstall)");
    return module;
}

OiioModule* load() {
    if (void* linked = ::dlsym(RTLD_DEFAULT, kEntry)) return fromEntry(linked, "(linked)");
    const std::vector<fs::path> paths = candidates();
    std::string why = "not found";
    for (const fs::path& path : paths) {
        std::error_code ec;
        if (!fs::exists(path, ec)) continue;
        void* handle = ::dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);  // never closed
        if (!handle) {
            const char* error = ::dlerror();
            why = error ? error : "dlopen failed";
            break;
        }
        void* symbol = ::dlsym(handle, kEntry);
        if (!symbol) throw RuntimeError(path.string() + ": not a penumbra OpenImageIO module");
        return fromEntry(symbol, path.string());
    }
    std::string where = paths.empty() ? kModuleFile : paths.front().string();
    if (paths.size() > 1) where += " or " + paths.back().string();
    throw RuntimeError("cannot load the OpenImageIO module " + where +
                       " (needed to read images and draw contact sheets): " + why);
}

}  // namespace

OiioModule& oiioModule() {
    static std::mutex mutex;
    static OiioModule* module = nullptr;
    const std::lock_guard lock(mutex);
    if (!module) module = load();  // a failure is thrown again on the next call
    return *module;
}

}  // namespace penumbra
