// A render job's checks of its input: the file is a scene, the technique exists, each -D
// technique key is valid alone, and the image and maps fit this GL's limits.
#pragma once

#include <filesystem>
#include <string>

#include "renderer/app/render_job.h"
#include "renderer/core/params.h"
#include "renderer/gl/context.h"
#include "renderer/scene/scene.h"
#include "renderer/techniques/technique.h"

namespace penumbra::app {

// S's technique; else InputError naming --technique (when REQ gave it) or the scene's key.
const techniques::TechniqueInfo& findTechniqueOrThrow(const scene::Scene& s,
                                                      const RenderRequest& req);

// S's technique block resolved against INFO's table (errors name "<scene>: technique").
Params resolveFor(const techniques::TechniqueInfo& info, const scene::Scene& s);

// Each -D technique.KEY=VALUE checked alone first, so that its error names the flag.
void checkTechniqueOverrides(const techniques::TechniqueInfo& info, const RenderRequest& req);

// Image size, the technique's parameters its table limits by GL (ParamSpec::limited_by) and
// light count against INFO's limits: InputError naming the key.
void checkGlLimits(const scene::Scene& s, const techniques::TechniqueInfo& technique,
                   const Params& params, const gl::ContextInfo& info);

}  // namespace penumbra::app
