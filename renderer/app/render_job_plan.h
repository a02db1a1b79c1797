// The frames a render job makes and the files each writes, all checked before any GL: frame
// numbers, animation range, output patterns and extensions, folders that accept new files.
#pragma once

#include <string>
#include <vector>

#include "renderer/app/render_job.h"

namespace penumbra::app {

struct FramePlan {
    int frame = 0;
    std::string exr, timing, preview;  // preview "" when not asked for
    bool skip = false;                 // --skip-existing and every file of the frame is there
};

// -f, else the scene's animation range, else frame 0. Negative frames are refused; a frame
// outside the scene's animation range is a warning on stderr (an InputError with --strict).
std::vector<int> chooseFrames(const RenderRequest& req, const scene::SceneSource& source);

// Each frame's EXR, timing JSON and preview. Throws InputError naming the flag for a pattern
// with no # where several frames (or a farm task, --frame-from-env) would share it, a wrong
// extension, two frames writing one file, or an output that is not a regular file.
std::vector<FramePlan> planFrames(const RenderRequest& req, const std::string& scene_name,
                                  const std::vector<int>& frames);

// Throws InputError naming the flag when a file of PLANS is one of INPUTS (the scene's
// inputFiles()): the render would overwrite what it reads, e.g. -o scene.exr beside scene.json,
// whose timing JSON is scene.json.
void checkOutputsAreNotInputs(const RenderRequest& req, const std::vector<FramePlan>& plans,
                              const std::vector<std::string>& inputs);

// Every folder the plans write into must exist or be creatable, and accept a new file (tried
// with a probe file, so it holds for root and read-only mounts). Throws InputError.
void checkOutputFolders(const std::vector<FramePlan>& plans);

// Removes the temporaries of the plans' files that dead processes left behind.
void removeStaleTemporaries(const std::vector<FramePlan>& plans);

}  // namespace penumbra::app
