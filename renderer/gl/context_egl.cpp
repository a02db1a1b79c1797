// EGL device and surfaceless backends: see context_egl.h.
#include "renderer/gl/context_egl.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <glad/gl.h>

#include <cstring>
#include <vector>

namespace penumbra::gl {
namespace {

struct EglFunctions {
    PFNEGLQUERYDEVICESEXTPROC queryDevices = nullptr;
    PFNEGLQUERYDEVICESTRINGEXTPROC queryDeviceString = nullptr;
    PFNEGLGETPLATFORMDISPLAYEXTPROC getPlatformDisplay = nullptr;
};

EglFunctions loadEglFunctions() {
    EglFunctions f;
    f.queryDevices =
        reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
    f.queryDeviceString = reinterpret_cast<PFNEGLQUERYDEVICESTRINGEXTPROC>(
        eglGetProcAddress("eglQueryDeviceStringEXT"));
    f.getPlatformDisplay = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
        eglGetProcAddress("eglGetPlatformDisplayEXT"));
    return f;
}

bool hasExtension(const char* list, const char* name) {
    if (!list) return false;
    size_t n = std::strlen(name);
    for (const char* p = list; (p = std::strstr(p, name)) != nullptr; p += n)
        if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
    return false;
}

std::vector<EGLDeviceEXT> queryDevices(const EglFunctions& f) {
    std::vector<EGLDeviceEXT> devices;
    if (!f.queryDevices) return devices;
    EGLint count = 0;
    if (!f.queryDevices(0, nullptr, &count) || count <= 0) return devices;
    devices.resize(static_cast<size_t>(count));
    f.queryDevices(count, devices.data(), &count);
    devices.resize(static_cast<size_t>(count));
    return devices;
}

EglDeviceInfo describeDevice(const EglFunctions& f, EGLDeviceEXT device, int index) {
    EglDeviceInfo info;
    info.index = index;
    const char* ext = f.queryDeviceString ? f.queryDeviceString(device, EGL_EXTENSIONS) : nullptr;
    info.software = hasExtension(ext, "EGL_MESA_device_software");
    const char* drm = nullptr;
    if (hasExtension(ext, "EGL_EXT_device_drm"))
        drm = f.queryDeviceString(device, EGL_DRM_DEVICE_FILE_EXT);
    if (drm)
        info.name = drm;
    else if (info.software)
        info.name = "Mesa software device";
    else
        info.name = "EGL device " + std::to_string(index);
    return info;
}

class EglContext final : public Context {
public:
    EglContext(EGLDisplay display, EGLContext context) : display_(display), context_(context) {}
    ~EglContext() override {
        eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        eglDestroyContext(display_, context_);
        eglTerminate(display_);
    }
    void setInfo(std::string api, std::string device) {
        info_.api = std::move(api);
        info_.device = std::move(device);
        fillContextInfo(info_);
    }

private:
    EGLDisplay display_;
    EGLContext context_;
};

std::string eglErrorName(EGLint e) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "EGL error 0x%04x", static_cast<unsigned>(e));
    return buf;
}

// Initialises DISPLAY, creates a GL core context (4.6, else 4.5, else 4.3), makes it current
// without a surface and loads GL through glad. Returns nullptr with WHY on failure.
std::unique_ptr<EglContext> makeContext(EGLDisplay display, bool debug, std::string& why) {
    if (display == EGL_NO_DISPLAY) {
        why = "no display";
        return nullptr;
    }
    EGLint major = 0, minor = 0;
    if (!eglInitialize(display, &major, &minor)) {
        why = "eglInitialize failed (" + eglErrorName(eglGetError()) + ")";
        return nullptr;
    }
    const char* ext = eglQueryString(display, EGL_EXTENSIONS);
    if (!hasExtension(ext, "EGL_KHR_surfaceless_context")) {
        why = "display lacks EGL_KHR_surfaceless_context";
        eglTerminate(display);
        return nullptr;
    }
    if (!eglBindAPI(EGL_OPENGL_API)) {
        why = "eglBindAPI(EGL_OPENGL_API) failed: no desktop OpenGL";
        eglTerminate(display);
        return nullptr;
    }
    EGLConfig config = EGL_NO_CONFIG_KHR;
    if (!hasExtension(ext, "EGL_KHR_no_config_context")) {
        const EGLint attribs[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
        EGLint n = 0;
        if (!eglChooseConfig(display, attribs, &config, 1, &n) || n < 1) {
            why = "no EGL config for desktop OpenGL";
            eglTerminate(display);
            return nullptr;
        }
    }
    EGLContext context = EGL_NO_CONTEXT;
    const int versions[][2] = {{4, 6}, {4, 5}, {4, 3}};
    for (const auto& v : versions) {
        const EGLint attribs[] = {EGL_CONTEXT_MAJOR_VERSION,
                                  v[0],
                                  EGL_CONTEXT_MINOR_VERSION,
                                  v[1],
                                  EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                  EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                  EGL_CONTEXT_OPENGL_DEBUG,
                                  debug ? EGL_TRUE : EGL_FALSE,
                                  EGL_NONE};
        context = eglCreateContext(display, config, EGL_NO_CONTEXT, attribs);
        if (context != EGL_NO_CONTEXT) break;
    }
    if (context == EGL_NO_CONTEXT) {
        why = "no OpenGL 4.3+ core context (" + eglErrorName(eglGetError()) + ")";
        eglTerminate(display);
        return nullptr;
    }
    if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context)) {
        why = "eglMakeCurrent failed (" + eglErrorName(eglGetError()) + ")";
        eglDestroyContext(display, context);
        eglTerminate(display);
        return nullptr;
    }
    auto result = std::make_unique<EglContext>(display, context);
    if (!gladLoadGL(reinterpret_cast<GLADloadfunc>(eglGetProcAddress))) {
        why = "glad could not load OpenGL through eglGetProcAddress";
        return nullptr;
    }
    return result;
}

}  // namespace

std::vector<EglDeviceInfo> Context::listEglDevices() {
    EglFunctions f = loadEglFunctions();
    std::vector<EglDeviceInfo> out;
    auto devices = queryDevices(f);
    for (size_t i = 0; i < devices.size(); ++i)
        out.push_back(describeDevice(f, devices[i], static_cast<int>(i)));
    return out;
}

std::unique_ptr<Context> createEglDeviceContext(std::optional<int> device, bool debug,
                                                std::string& why) {
    EglFunctions f = loadEglFunctions();
    if (!f.queryDevices || !f.getPlatformDisplay) {
        why = "EGL_EXT_device_enumeration / EGL_EXT_platform_device not available";
        return nullptr;
    }
    auto devices = queryDevices(f);
    if (devices.empty()) {
        why = "no EGL devices";
        return nullptr;
    }
    std::vector<int> order;
    if (device) {
        if (*device < 0 || *device >= static_cast<int>(devices.size())) {
            why = "--device " + std::to_string(*device) + " out of range (" +
                  std::to_string(devices.size()) + " EGL devices)";
            return nullptr;
        }
        order.push_back(*device);
    } else {
        // Hardware devices first, then software.
        for (int pass = 0; pass < 2; ++pass)
            for (size_t i = 0; i < devices.size(); ++i)
                if (describeDevice(f, devices[i], static_cast<int>(i)).software == (pass == 1))
                    order.push_back(static_cast<int>(i));
    }
    std::string reasons;
    for (int i : order) {
        EglDeviceInfo d = describeDevice(f, devices[static_cast<size_t>(i)], i);
        EGLDisplay display =
            f.getPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, devices[static_cast<size_t>(i)], nullptr);
        std::string r;
        auto ctx = makeContext(display, debug, r);
        if (ctx) {
            ctx->setInfo("egl-device", "EGL device " + std::to_string(i) + ": " + d.name);
            return ctx;
        }
        reasons += (reasons.empty() ? "" : "; ") +
                   ("device " + std::to_string(i) + " (" + d.name + "): " + r);
    }
    why = reasons;
    return nullptr;
}

std::unique_ptr<Context> createEglSurfacelessContext(bool debug, std::string& why) {
    EglFunctions f = loadEglFunctions();
    const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (!f.getPlatformDisplay || !hasExtension(client, "EGL_MESA_platform_surfaceless")) {
        why = "EGL_MESA_platform_surfaceless not available";
        return nullptr;
    }
    EGLDisplay display =
        f.getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    auto ctx = makeContext(display, debug, why);
    if (ctx) ctx->setInfo("egl-surfaceless", "Mesa surfaceless platform");
    return ctx;
}

}  // namespace penumbra::gl
