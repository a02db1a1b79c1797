// `penumbra render` as a job: load and validate everything, create the context, then for each
// frame render (warmup + repeats), read back, and write EXR, timing JSON and preview.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "renderer/frame/render_frame.h"
#include "renderer/gl/context.h"
#include "renderer/output/exr.h"
#include "renderer/scene/scene_source.h"

namespace penumbra::app {

struct RenderRequest {
    std::filesystem::path scene;
    std::vector<scene::Override> overrides;  // -D, in order (--size is added as overrides)
    std::optional<std::string> technique;    // -t
    scene::GltfSceneOptions gltf;            // --light-size, --no-floor (a .gltf/.glb scene)
    std::optional<std::string> output;       // -o PATTERN
    std::optional<std::string> timings;      // --timings PATTERN
    std::optional<std::string> preview;      // --preview PATTERN
    output::ExrCompression exr_compression;  // --exr-compression
    std::optional<std::string> frames;       // -f SPEC
    std::string frames_flag = "--frames";    // where FRAMES came from, for messages
    bool farm_task = false;  // --frame-from-env: one task of many, so patterns need a #
    bool strict = false;     // --strict: a frame outside the animation range is an error
    gl::ContextRequest gl;
    bool skip_existing = false;
    bool list_frames = false;  // print the frames to render (stdout) and stop: no GL
    frame::FrameRuns runs;     // --warmup, --repeat
    bool quiet = false;
};

// "unknown technique 'NAME' (did you mean 'X'? known: a, b, ...)" (render_job_checks.cpp).
std::string unknownTechniqueMessage(const std::string& name);

// Returns the exit code (0, or 1 when a frame failed at run time). Throws InputError (bad
// input, before anything is written) and BackendError (no context).
int runRenderJob(const RenderRequest& request);

}  // namespace penumbra::app
