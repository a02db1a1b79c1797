// The backend flags shared by `render` and `info`: --backend auto|egl|osmesa, --device N,
// --gl-debug.
#pragma once

#include "cli/args.h"
#include "renderer/gl/context.h"

namespace penumbra::cli {

// Consumes one backend flag at the cursor into REQUEST; false if the argument is not one.
bool parseBackendFlag(ArgCursor& c, gl::ContextRequest& request);

}  // namespace penumbra::cli
