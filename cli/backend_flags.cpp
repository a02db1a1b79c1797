// Backend flags: see backend_flags.h.
#include "cli/backend_flags.h"

namespace penumbra::cli {

bool parseBackendFlag(ArgCursor& c, gl::ContextRequest& request) {
    if (auto v = c.option("", "--backend")) {
        if (*v == "auto")
            request.backend = gl::Backend::Auto;
        else if (*v == "egl")
            request.backend = gl::Backend::Egl;
        else if (*v == "egl-device")
            request.backend = gl::Backend::EglDevice;
        else if (*v == "egl-surfaceless")
            request.backend = gl::Backend::EglSurfaceless;
        else if (*v == "osmesa")
            request.backend = gl::Backend::OSMesa;
        else
            c.fail("--backend: expected auto, egl, egl-device, egl-surfaceless or osmesa, got '" +
                   *v + "'");
        return true;
    }
    if (auto v = c.option("", "--device")) {
        request.device = parseInt(c, "--device", *v, 0, 64);
        return true;
    }
    if (c.flag("", "--gl-debug")) {
        request.debug = true;
        return true;
    }
    return false;
}

}  // namespace penumbra::cli
