// The paper's CPU path (Atty et al. 4.1): the occluder map read back and turned into a list of
// micro-patches on the host, uploaded for the splat pass to expand into penumbra quads.
#pragma once

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

#include "renderer/gl/handles.h"
#include "renderer/passes/light_windows.h"

namespace penumbra::techniques::ssm {

// std430 mirror of Patch in glsl/techniques/ssm/splat.vert and compact.comp.
struct MicroPatch {
    // y * map size + x, plus the level L << kLevelShift: the patch is the 2^L x 2^L texels from
    // this one (lod.comp merges blocks; 0 without `lod`)
    std::uint32_t texel;
    float z;       // distance from the light (a merged patch's: the middle of its depths)
    float z_near;  // its nearest micro-patch's (z when unmerged)
};
static_assert(sizeof(MicroPatch) == 12);
inline constexpr int kLevelShift = 24;  // maps up to 4096^2 = 2^24 texels

// Reads the MAP_SIZE^2 occluder map SOURCE (window WINDOW) back and appends one micro-patch per
// texel that is not EMPTY (the cleared depth) to PATCHES (cleared first). SOURCE is the linear
// depth map, or with MERGED lod.comp's map of (depth, level, nearest depth, 0).
void readMicroPatches(const gl::Texture& source, bool merged, int map_size,
                      const passes::LightWindow& window, float empty, std::vector<float>& scratch,
                      std::vector<MicroPatch>& patches);

}  // namespace penumbra::techniques::ssm
