// Backend selection and context information: see context.h.
#include "renderer/gl/context.h"

#include <glad/gl.h>

#include <cstring>

#include "renderer/core/error.h"
#include "renderer/gl/context_egl.h"
#include "renderer/gl/context_osmesa.h"
#include "renderer/gl/program_cache.h"

namespace penumbra::gl {
namespace {

int glInt(GLenum name) {
    GLint v = 0;
    glGetIntegerv(name, &v);
    return v;
}

bool hasGlExtension(const char* name) {
    GLint n = 0;
    glGetIntegerv(GL_NUM_EXTENSIONS, &n);
    for (GLint i = 0; i < n; ++i) {
        const GLubyte* e = glGetStringi(GL_EXTENSIONS, static_cast<GLuint>(i));
        if (e && std::strcmp(reinterpret_cast<const char*>(e), name) == 0) return true;
    }
    return false;
}

bool isSoftwareRenderer(const std::string& renderer) {
    for (const char* s : {"llvmpipe", "softpipe", "swrast", "SwiftShader", "lavapipe"})
        if (renderer.find(s) != std::string::npos) return true;
    return false;
}

}  // namespace

std::string glString(unsigned int name) {
    const GLubyte* s = glGetString(name);
    return s ? reinterpret_cast<const char*>(s) : "";
}

void fillContextInfo(ContextInfo& info) {
    info.vendor = glString(GL_VENDOR);
    info.renderer = glString(GL_RENDERER);
    info.version = glString(GL_VERSION);
    info.glsl_version = glString(GL_SHADING_LANGUAGE_VERSION);
    info.major = glInt(GL_MAJOR_VERSION);
    info.minor = glInt(GL_MINOR_VERSION);
    info.software = isSoftwareRenderer(info.renderer);
    info.max_texture_size = glInt(GL_MAX_TEXTURE_SIZE);
    info.max_array_layers = glInt(GL_MAX_ARRAY_TEXTURE_LAYERS);
    info.max_renderbuffer_size = glInt(GL_MAX_RENDERBUFFER_SIZE);
    info.max_samples = glInt(GL_MAX_SAMPLES);
    info.max_color_attachments = glInt(GL_MAX_COLOR_ATTACHMENTS);
    info.has_vertex_layer = hasGlExtension("GL_ARB_shader_viewport_layer_array") ||
                            hasGlExtension("GL_AMD_vertex_shader_layer");
}

nlohmann::json ContextInfo::toJson() const {
    return {{"api", api},
            {"device", device},
            {"vendor", vendor},
            {"renderer", renderer},
            {"version", version},
            {"glsl_version", glsl_version},
            {"software", software},
            {"timer", software ? "cpu_glfinish" : "gl_timer_query"},
            {"limits",
             {{"max_texture_size", max_texture_size},
              {"max_array_texture_layers", max_array_layers},
              {"max_renderbuffer_size", max_renderbuffer_size},
              {"max_samples", max_samples},
              {"max_color_attachments", max_color_attachments},
              {"vertex_shader_layer", has_vertex_layer}}}};
}

std::unique_ptr<Context> Context::create(const ContextRequest& request) {
    if (request.device) {
        auto devices = listEglDevices();
        if (*request.device < 0 || *request.device >= static_cast<int>(devices.size())) {
            std::string list;
            for (const auto& d : devices)
                list += (list.empty() ? "" : ", ") + std::to_string(d.index) + ": " + d.name;
            throw InputError("--device " + std::to_string(*request.device) +
                             ": no such EGL device (" +
                             (list.empty() ? std::string("none found") : list) + ")");
        }
        if (request.backend == Backend::OSMesa || request.backend == Backend::EglSurfaceless)
            throw InputError("--device: only the EGL device backend has devices");
    }
    createProgramCacheFolder();  // before the driver looks for its own cache beside it
    std::vector<BackendProbe> probes;
    std::unique_ptr<Context> ctx;
    auto attempt = [&](const char* name, auto&& make) {
        if (ctx) return;
        std::string why;
        ctx = make(why);
        probes.push_back({name, ctx ? ctx->info_.renderer : why, ctx != nullptr});
    };
    const bool debug = request.debug;
    const Backend b = request.backend;
    const bool any_egl = b == Backend::Auto || b == Backend::Egl;
    if (any_egl || b == Backend::EglDevice)
        attempt("egl-device", [&](std::string& why) {
            return createEglDeviceContext(request.device, debug, why);
        });
    if ((any_egl && !request.device) || b == Backend::EglSurfaceless)
        attempt("egl-surfaceless",
                [&](std::string& why) { return createEglSurfacelessContext(debug, why); });
    // A chosen device is a promise: no silent fallback to another backend.
    if ((b == Backend::Auto && !request.device) || b == Backend::OSMesa)
        attempt("osmesa", [&](std::string& why) { return createOSMesaContext(debug, why); });
    if (!ctx) {
        std::string msg = "no usable OpenGL backend; tried ";
        for (size_t i = 0; i < probes.size(); ++i)
            msg += (i ? "; " : "") + probes[i].name + ": " + probes[i].detail;
        throw BackendError(msg);
    }
    ctx->probes_ = std::move(probes);
    return ctx;
}

}  // namespace penumbra::gl
