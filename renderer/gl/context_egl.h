// EGL backends: a device display (EGL_EXT_platform_device) or Mesa's surfaceless platform,
// a GL core context with no surface (we render to framebuffer objects only).
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "renderer/gl/context.h"

namespace penumbra::gl {

// Each returns nullptr and fills WHY when the backend is not usable.
std::unique_ptr<Context> createEglDeviceContext(std::optional<int> device, bool debug,
                                                std::string& why);
std::unique_ptr<Context> createEglSurfacelessContext(bool debug, std::string& why);

}  // namespace penumbra::gl
