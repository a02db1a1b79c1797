// The OSMesa backend, loaded at run time with dlopen: Mesa 25.1 removed OSMesa, so it is
// optional, and the binary links only libEGL.
#pragma once

#include <memory>
#include <string>

#include "renderer/gl/context.h"

namespace penumbra::gl {

// Returns nullptr and fills WHY when libOSMesa is missing or gives no core context.
std::unique_ptr<Context> createOSMesaContext(bool debug, std::string& why);

}  // namespace penumbra::gl
