// The headless OpenGL context: EGL device (hardware first, then Mesa's software device),
// EGL surfaceless, or OSMesa (dlopen'ed, optional), with GL 4.5 core loaded through glad2.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace penumbra::gl {

// Egl tries the device platform, then surfaceless; the two may also be asked for alone.
enum class Backend { Auto, Egl, EglDevice, EglSurfaceless, OSMesa };

struct ContextRequest {
    Backend backend = Backend::Auto;
    std::optional<int> device;  // --device N: index into the EGL device list
    bool debug = false;         // --gl-debug: debug context + synchronous KHR_debug output
};

// What one backend attempt found (for `penumbra info` and the exit-3 message).
struct BackendProbe {
    std::string name;    // "egl-device", "egl-surfaceless", "osmesa"
    std::string detail;  // device name / extension / why it failed
    bool usable = false;
};

struct EglDeviceInfo {
    int index = 0;
    std::string name;  // DRM node or driver name
    bool software = false;
};

struct ContextInfo {
    std::string api;     // "egl-device", "egl-surfaceless", "osmesa"
    std::string device;  // device description
    std::string vendor, renderer, version, glsl_version;
    int major = 0, minor = 0;
    bool software = false;  // a software rasteriser (llvmpipe, softpipe, ...): timer queries lie
    int max_texture_size = 0, max_array_layers = 0, max_renderbuffer_size = 0;
    int max_samples = 0, max_color_attachments = 0;
    bool has_vertex_layer = false;  // gl_Layer writable from the vertex shader
    nlohmann::json toJson() const;
};

class Context {
public:
    // Creates and makes current a context as REQUEST asks. Throws BackendError (exit 3) naming
    // every backend tried and why it failed.
    static std::unique_ptr<Context> create(const ContextRequest& request);
    // Lists EGL devices without creating a context.
    static std::vector<EglDeviceInfo> listEglDevices();

    virtual ~Context() = default;
    const ContextInfo& info() const { return info_; }
    const std::vector<BackendProbe>& probes() const { return probes_; }

protected:
    ContextInfo info_;
    std::vector<BackendProbe> probes_;
    friend struct ContextFactory;
};

// Reads GL strings and limits from the current context (after glad has loaded).
void fillContextInfo(ContextInfo& info);

// The current context's string NAME (glGetString: GL_VENDOR, GL_RENDERER, ...), empty where the
// driver gives none.
std::string glString(unsigned int name);

}  // namespace penumbra::gl
