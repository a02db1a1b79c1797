// OSMesa backend through dlopen: see context_osmesa.h. The few OSMesa declarations needed are
// written here, so the build needs no OSMesa headers and the binary no OSMesa library.
#include "renderer/gl/context_osmesa.h"

#include <dlfcn.h>
#include <glad/gl.h>

#include <cstdlib>
#include <vector>

namespace penumbra::gl {
namespace {

using OSMesaContextHandle = void*;
using CreateContextAttribs = OSMesaContextHandle (*)(const int*, OSMesaContextHandle);
using MakeCurrent = unsigned char (*)(OSMesaContextHandle, void*, unsigned, int, int);
using DestroyContext = void (*)(OSMesaContextHandle);
using GetProcAddress = void* (*)(const char*);

// Values from Mesa's GL/osmesa.h.
constexpr int kOSMesaFormat = 0x22;
constexpr int kOSMesaRgba = 0x1908;  // GL_RGBA
constexpr int kOSMesaDepthBits = 0x30;
constexpr int kOSMesaProfile = 0x33;
constexpr int kOSMesaCoreProfile = 0x34;
constexpr int kOSMesaMajor = 0x36;
constexpr int kOSMesaMinor = 0x37;
constexpr unsigned kUnsignedByte = 0x1401;

GetProcAddress g_getProcAddress = nullptr;

GLADapiproc loadProc(const char* name) {
    return reinterpret_cast<GLADapiproc>(g_getProcAddress(name));
}

class OSMesaContext final : public Context {
public:
    OSMesaContext(void* library, OSMesaContextHandle context, DestroyContext destroy)
        : library_(library), context_(context), destroy_(destroy), buffer_(4 * 4 * 4) {}
    ~OSMesaContext() override {
        destroy_(context_);
        // The library stays loaded: Mesa keeps thread-local state that outlives the context.
        (void)library_;
    }
    void* buffer() { return buffer_.data(); }
    void setInfo() {
        info_.api = "osmesa";
        info_.device = "OSMesa (Mesa offscreen)";
        fillContextInfo(info_);
    }

private:
    void* library_;
    OSMesaContextHandle context_;
    DestroyContext destroy_;
    std::vector<unsigned char> buffer_;  // the 4x4 surface OSMesa insists on; we use FBOs
};

}  // namespace

std::unique_ptr<Context> createOSMesaContext(bool /*debug*/, std::string& why) {
    void* lib = nullptr;
    // PENUMBRA_OSMESA_LIBRARY names another build of libOSMesa (e.g. a Mesa built by hand).
    const char* override_name = std::getenv("PENUMBRA_OSMESA_LIBRARY");
    if (override_name && *override_name) {
        lib = dlopen(override_name, RTLD_NOW | RTLD_LOCAL);
        if (!lib) {
            why = std::string("PENUMBRA_OSMESA_LIBRARY=") + override_name + ": " + dlerror();
            return nullptr;
        }
    }
    for (const char* name : {"libOSMesa.so.8", "libOSMesa.so.6", "libOSMesa.so"})
        if (!lib && (lib = dlopen(name, RTLD_NOW | RTLD_LOCAL)) != nullptr) break;
    if (!lib) {
        why = "libOSMesa not found (Debian package libosmesa6)";
        return nullptr;
    }
    auto create = reinterpret_cast<CreateContextAttribs>(dlsym(lib, "OSMesaCreateContextAttribs"));
    auto makeCurrent = reinterpret_cast<MakeCurrent>(dlsym(lib, "OSMesaMakeCurrent"));
    auto destroy = reinterpret_cast<DestroyContext>(dlsym(lib, "OSMesaDestroyContext"));
    auto getProc = reinterpret_cast<GetProcAddress>(dlsym(lib, "OSMesaGetProcAddress"));
    if (!create || !makeCurrent || !destroy || !getProc) {
        why = "libOSMesa lacks OSMesaCreateContextAttribs";
        return nullptr;
    }
    OSMesaContextHandle handle = nullptr;
    const int versions[][2] = {{4, 6}, {4, 5}, {4, 3}};
    for (const auto& v : versions) {
        const int attribs[] = {kOSMesaFormat,
                               kOSMesaRgba,
                               kOSMesaDepthBits,
                               0,
                               kOSMesaProfile,
                               kOSMesaCoreProfile,
                               kOSMesaMajor,
                               v[0],
                               kOSMesaMinor,
                               v[1],
                               0};
        handle = create(attribs, nullptr);
        if (handle) break;
    }
    if (!handle) {
        why = "OSMesa gave no OpenGL 4.3+ core context";
        return nullptr;
    }
    auto ctx = std::make_unique<OSMesaContext>(lib, handle, destroy);
    if (!makeCurrent(handle, ctx->buffer(), kUnsignedByte, 4, 4)) {
        why = "OSMesaMakeCurrent failed";
        return nullptr;
    }
    g_getProcAddress = getProc;
    if (!gladLoadGL(loadProc)) {
        why = "glad could not load OpenGL through OSMesaGetProcAddress";
        return nullptr;
    }
    ctx->setInfo();
    return ctx;
}

}  // namespace penumbra::gl
