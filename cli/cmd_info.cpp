// `penumbra info [--json]`: the backends found, the one chosen, GL version, renderer, limits.
#include <cstdio>
#include <iostream>

#include "cli/backend_flags.h"
#include "cli/commands.h"
#include "penumbra/version.h"

namespace penumbra::cli {
namespace {

constexpr const char* kHelp =
    R"(usage: penumbra info [--json] [--backend auto|egl|egl-device|egl-surfaceless|osmesa]
                     [--device N]

Creates an OpenGL context the way `render` would and reports what it found: every backend
tried (EGL device, EGL surfaceless, OSMesa), the EGL devices, the one chosen, its GL vendor,
renderer and version, the clock used for timings, and the limits that matter.
Exit 0 when a backend works, 3 when none does.
)";

}  // namespace

int runInfo(const Args& args) {
    ArgCursor c("info", args);
    bool json = false;
    gl::ContextRequest request;
    while (!c.done()) {
        if (c.flag("-h", "--help")) {
            std::fputs(kHelp, stdout);
            return 0;
        }
        if (c.flag("", "--json")) {
            json = true;
            continue;
        }
        if (parseBackendFlag(c, request)) continue;
        c.unknown();
    }
    auto devices = gl::Context::listEglDevices();
    auto ctx = gl::Context::create(request);
    const auto& info = ctx->info();
    if (json) {
        nlohmann::json j;
        j["version"] = PENUMBRA_VERSION;
        j["commit"] = PENUMBRA_COMMIT;
        j["egl_devices"] = nlohmann::json::array();
        for (const auto& d : devices)
            j["egl_devices"].push_back(
                {{"index", d.index}, {"name", d.name}, {"software", d.software}});
        j["tried"] = nlohmann::json::array();
        for (const auto& p : ctx->probes())
            j["tried"].push_back({{"backend", p.name}, {"usable", p.usable}, {"detail", p.detail}});
        j["chosen"] = info.toJson();
        std::cout << j.dump(2) << "\n";
        return 0;
    }
    std::printf("penumbra %s (%s)\n", PENUMBRA_VERSION, PENUMBRA_COMMIT);
    std::printf("EGL devices:\n");
    for (const auto& d : devices)
        std::printf("  %d: %s%s\n", d.index, d.name.c_str(), d.software ? " (software)" : "");
    if (devices.empty()) std::printf("  none\n");
    std::printf("backends tried:\n");
    for (const auto& p : ctx->probes())
        std::printf("  %-16s %s: %s\n", p.name.c_str(), p.usable ? "ok" : "no", p.detail.c_str());
    std::printf("chosen: %s (%s)\n", info.api.c_str(), info.device.c_str());
    std::printf("GL: %s | %s | %s | GLSL %s\n", info.vendor.c_str(), info.renderer.c_str(),
                info.version.c_str(), info.glsl_version.c_str());
    std::printf("timings: %s\n", info.software
                                     ? "glFinish-bracketed CPU clock (software rasteriser)"
                                     : "GL timer queries");
    std::printf(
        "limits: texture %d, array layers %d, samples %d, colour attachments %d, "
        "vertex-shader gl_Layer %s\n",
        info.max_texture_size, info.max_array_layers, info.max_samples, info.max_color_attachments,
        info.has_vertex_layer ? "yes" : "no");
    return 0;
}

}  // namespace penumbra::cli
