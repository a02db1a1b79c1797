// The flags `render` and `sweep` share, parsed once with one set of limits: --size WxH (as the
// overrides image.width and image.height), --warmup N (0 to 100) and --repeat N (1 to 100).
#pragma once

#include <vector>

#include "cli/args.h"
#include "renderer/frame/render_frame.h"
#include "renderer/scene/scene_source.h"

namespace penumbra::cli {

inline constexpr int kMaxWarmup = 100;  // untimed renders per frame
inline constexpr int kMaxRepeat = 100;  // timed renders per frame

// Consumes one of the flags at the cursor into OVERRIDES or RUNS; false if the argument is
// none of them.
bool parseRunFlag(ArgCursor& c, std::vector<scene::Override>& overrides, frame::FrameRuns& runs);

}  // namespace penumbra::cli
