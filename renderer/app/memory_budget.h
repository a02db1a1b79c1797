// What a render will allocate, estimated from the scene's image and the technique's parameters
// before anything is allocated: refused (exit 2, the key named) over the memory limit, GL's
// limits, or the bound on ssm's splat work.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "renderer/core/params.h"
#include "renderer/gl/context.h"
#include "renderer/scene/scene.h"

namespace penumbra::app {

// ssm splats each of its map_size^2 micro-patches over up to ssm_size^2 texels: refused when
// map_size x ssm_size exceeds this (the default 256 x 256 is 2^16).
constexpr std::uint64_t kMaxSsmSplatProduct = std::uint64_t{1} << 21;

// llvmpipe fails a single texture over 2 GiB (measured: a 4096^2 x 32 depth array renders,
// x 33 is "framebuffer incomplete"); other drivers' limit is only the memory.
constexpr std::uint64_t kSoftwareTextureLimit = std::uint64_t{2} << 30;

// One allocation the render implies: the key that sizes it and its bytes.
struct MemoryTerm {
    std::string key;           // "image.width", "image.samples", "technique.map_size", ...
    std::string what;          // "the G-buffer", "shadow map array (4096^2 x 32)", ...
    std::uint64_t bytes = 0;   // the whole allocation
    bool one_texture = false;  // a single GL texture (checked against kSoftwareTextureLimit)
};

// The terms for S rendered with TECHNIQUE and its resolved PARAMS (approximate: the largest
// buffers, not every small one). FRAMES_IN_FLIGHT: frames whose readback or image is alive at
// once (a sequence reads one back and writes another while the next renders).
std::vector<MemoryTerm> estimateMemory(const scene::Scene& s, std::string_view technique,
                                       const Params& params, int frames_in_flight = 1);

// Throws InputError("<scene>: <key>: ...") when the estimate exceeds the memory limit (naming
// the largest term's key), a texture exceeds GL's size limit or llvmpipe's per-texture limit
// (GL given), or ssm's splat work exceeds kMaxSsmSplatProduct. GL may be null (no context yet).
void checkMemoryBudget(const scene::Scene& s, std::string_view technique, const Params& params,
                       const gl::ContextInfo* gl, int frames_in_flight = 1);

}  // namespace penumbra::app
