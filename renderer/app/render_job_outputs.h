// What a render job writes per frame: the scene's canonical name for headers, and the frame's
// files (preview, timing JSON, EXR) committed as one unit with the EXR renamed into place last.
#pragma once

#include <filesystem>
#include <string>

#include "renderer/app/render_job_plan.h"
#include "renderer/output/exr.h"
#include "renderer/output/image.h"
#include "renderer/output/timing.h"

namespace penumbra::app {

// The scene as outputs name it, the same however the path was typed: relative to the working
// directory when the file lies below it ("scenes/walk.json"), else its file name and content
// hash ("walk.json@0123456789abcdef").
std::string canonicalScenePath(const std::filesystem::path& scene);

// Writes PLAN's preview (if any), timing JSON and EXR (with COMPRESSION) under temporary names,
// then renames them in that order: the EXR exists only when every file of the frame does.
// Throws RuntimeError.
void writeFrameFiles(const FramePlan& plan, const output::Image& image,
                     const output::FrameReport& report, const output::ExrCompression& compression);

}  // namespace penumbra::app
