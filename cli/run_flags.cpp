// The flags render and sweep share: see run_flags.h.
#include "cli/run_flags.h"

#include <string>

namespace penumbra::cli {

bool parseRunFlag(ArgCursor& c, std::vector<scene::Override>& overrides, frame::FrameRuns& runs) {
    if (auto v = c.option("", "--size")) {
        auto [w, h] = parseSize(c, "--size", *v);
        overrides.push_back({"image.width", std::to_string(w)});
        overrides.push_back({"image.height", std::to_string(h)});
        return true;
    }
    if (auto v = c.option("", "--warmup")) {
        runs.warmup = parseInt(c, "--warmup", *v, 0, kMaxWarmup);
        return true;
    }
    if (auto v = c.option("", "--repeat")) {
        runs.repeat = parseInt(c, "--repeat", *v, 1, kMaxRepeat);
        return true;
    }
    return false;
}

}  // namespace penumbra::cli
