// What a render will allocate, estimated from the scene's image and the technique's parameters
// before anything is allocated: refused (exit 2, the key named) over the memory limit or a
// technique's own bound. Each technique lists its terms (TechniqueInfo::memory).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "renderer/core/memory_term.h"
#include "renderer/core/params.h"
#include "renderer/gl/context.h"
#include "renderer/scene/scene.h"
#include "renderer/techniques/technique.h"

namespace penumbra::app {

// llvmpipe fails a single texture over 2 GiB (measured: a 4096^2 x 32 depth array renders,
// x 33 is "framebuffer incomplete"); other drivers' limit is only the memory.
constexpr std::uint64_t kSoftwareTextureLimit = std::uint64_t{2} << 30;

// The terms for S rendered with TECHNIQUE and its resolved PARAMS (approximate: the largest
// buffers, not every small one): the frame's own, then the technique's. FRAMES_IN_FLIGHT:
// frames whose readback or image is alive at once (a sequence reads one back and writes another
// while the next renders).
std::vector<MemoryTerm> estimateMemory(const scene::Scene& s,
                                       const techniques::TechniqueInfo& technique,
                                       const Params& params, int frames_in_flight = 1);

// Throws InputError("<scene>: <key>: ...") when the technique's own bound refuses PARAMS
// (TechniqueInfo::limit_error), the estimate exceeds the memory limit (naming the largest term's
// key), or a texture exceeds llvmpipe's per-texture limit (GL given). GL may be null (no context
// yet). GL's size limits are the parameter table's (GlLimit, checkGlLimits).
void checkMemoryBudget(const scene::Scene& s, const techniques::TechniqueInfo& technique,
                       const Params& params, const gl::ContextInfo* gl, int frames_in_flight = 1);

}  // namespace penumbra::app
