// The flags of a scene made from a glTF file, shared by `render MODEL.glb` and `scene`:
// --light-size W[xH] (metres) and --no-floor.
#pragma once

#include "cli/args.h"
#include "renderer/scene/gltf_scene.h"

namespace penumbra::cli {

inline constexpr double kMinLightSize = 1e-6;  // metres, each side
inline constexpr double kMaxLightSize = 1e6;

// Consumes one of the flags at the cursor into OPTIONS; false if the argument is neither.
bool parseGltfSceneFlag(ArgCursor& c, scene::GltfSceneOptions& options);

// True when OPTIONS differ from the defaults (a flag was given).
bool gltfSceneFlagsGiven(const scene::GltfSceneOptions& options);

}  // namespace penumbra::cli
