// `penumbra sweep` as a job: the cartesian product of --vary axes rendered with one technique,
// each run compared against a reference rendered once per distinct image-changing setting and
// cached by a hash of what determines it; results as CSV, JSON, images and a report.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "renderer/core/sweep_spec.h"
#include "renderer/frame/render_frame.h"
#include "renderer/gl/context.h"
#include "renderer/scene/scene_source.h"

namespace penumbra::app {

struct SweepRequest {
    std::filesystem::path scene;
    std::vector<scene::Override> overrides;  // -D and --size, before the varied values
    std::optional<std::string> technique;    // -t
    std::vector<VaryAxis> axes;              // --vary
    std::string reference_technique = "exact";
    std::vector<scene::Override> reference_sets;  // --reference-set, after the defaults
    int frame = 0;
    std::filesystem::path out;  // -o DIR
    // --cache DIR: where references are kept, shared by sweeps (sweepCacheDefault()); empty
    // for DIR/cache, the sweep's own (--cache none).
    std::filesystem::path cache;
    gl::ContextRequest gl;
    frame::FrameRuns runs{1, 3};  // --warmup, --repeat
    bool quiet = false;
    bool report = true;  // run scripts/sweep-report at the end
    // --jobs N: render the runs as N parallel `penumbra sweep --run-index K` processes through
    // GNU parallel (the engine of scripts/sequence), then collect. JOB_ARGS are the sweep's own
    // arguments (without --jobs) for those processes.
    int jobs = 1;
    std::vector<std::string> job_args;
    std::optional<int> run_index;  // --run-index K (1-based): render run K only, no tables
};

// The reference cache shared by sweeps: $XDG_CACHE_HOME/penumbra/references, else
// $HOME/.cache/penumbra/references; empty (the sweep's own DIR/cache) when neither is set.
std::filesystem::path sweepCacheDefault();

// Returns 0, or 1 when a run or the report failed. Throws InputError for bad input (before any
// rendering) and BackendError.
int runSweepJob(const SweepRequest& request);

}  // namespace penumbra::app
