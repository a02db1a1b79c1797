// Frame lists in Blender style ("7", "1-120", "1-120:4", "1-3,5,9-20:2"), parsed and validated
// once; the renderer and the scene's animation range both use this.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace penumbra {

// Parses SPEC into the ascending, de-duplicated list of frames it names.
// Throws InputError("<where>: <what is wrong>") on a malformed or empty spec; WHERE names the
// flag or key the spec came from (e.g. "--frames" or "scene.json: animation.frames").
std::vector<int> parseFrameSpec(std::string_view spec, std::string_view where);

}  // namespace penumbra
