// The paper's CPU path (Atty et al. 4.1): the occluder map read back and turned into a list of
// micro-patches on the host, uploaded for the splat pass to expand into penumbra quads.
#pragma once

#include <glm/glm.hpp>

#include <array>
#include <cstdint>
#include <vector>

#include "glsl/techniques/ssm/bindings.glsl"
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
    // A merged block's plane (accumulate=samples, lod.comp): slopes of 1 / distance per texel
    // in x and y; 0 for a patch parallel to the light
    float slope_x;
    float slope_y;
};
static_assert(sizeof(MicroPatch) == 20);
inline constexpr int kLevelShift = 24;  // maps up to 4096^2 = 2^24 texels

// The splat's patch classes (glsl/techniques/ssm/bindings.glsl SSM_CLASS_*), each drawn by its
// own program from its own range of the list: unmerged, merged at one depth, merged on a plane.
inline constexpr int kPatchClasses = SSM_CLASSES;
inline int patchClass(const MicroPatch& p) {
    if ((p.texel >> kLevelShift) == 0) return SSM_CLASS_MICRO;
    return p.slope_x == 0.0f && p.slope_y == 0.0f ? SSM_CLASS_FLAT : SSM_CLASS_PLANE;
}
using ClassCounts = std::array<std::uint32_t, kPatchClasses>;

// Reads the MAP_SIZE^2 occluder map SOURCE (window WINDOW) back and lists one micro-patch per
// texel that is not EMPTY (the cleared depth) in PATCHES (cleared first), class by class and in
// row-major texel order within a class (compact.comp's order); returns each class's count.
// SOURCE is the linear depth map, or with SLOPES (merged) lod.comp's map of (depth, level,
// nearest depth, 0) and SLOPES its planes' slopes.
ClassCounts readMicroPatches(const gl::Texture& source, const gl::Texture* slopes, int map_size,
                             const passes::LightWindow& window, float empty,
                             std::vector<float>& scratch, std::vector<MicroPatch>& patches);

}  // namespace penumbra::techniques::ssm
