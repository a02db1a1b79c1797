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
    std::uint32_t texel;  // y * map size + x: the patch is this texel of the map's window
    float z;              // distance from the light's centre
};
static_assert(sizeof(MicroPatch) == 8);

// Reads the MAP_SIZE^2 linear-depth occluder map DEPTH (window WINDOW) back and appends one
// micro-patch per texel that is not EMPTY (the cleared depth) to PATCHES (cleared first).
void readMicroPatches(const gl::Texture& depth, int map_size, const passes::LightWindow& window,
                      float empty, std::vector<float>& scratch, std::vector<MicroPatch>& patches);

}  // namespace penumbra::techniques::ssm
