// Estimates of a render's buffers: see memory_budget.h. Sizes follow the passes' allocations
// (passes/gbuffer.cpp, sample_gbuffer.cpp, shade.cpp, frame/output_targets.cpp); each
// technique lists its own (TechniqueInfo::memory).
#include "renderer/app/memory_budget.h"

#include <algorithm>
#include <cstdint>

#include "renderer/core/error.h"
#include "renderer/core/memory_limit.h"

namespace penumbra::app {
namespace {

using u64 = std::uint64_t;

u64 product(std::initializer_list<u64> f) {
    return saturatingProduct(f);
}

}  // namespace

std::vector<MemoryTerm> estimateMemory(const scene::Scene& s,
                                       const techniques::TechniqueInfo& technique,
                                       const Params& params, int frames_in_flight) {
    const u64 pixels = product({static_cast<u64>(s.image.width), static_cast<u64>(s.image.height)});
    u64 lights = std::max<u64>(1, s.lights.size());
    if (s.environment && technique.environment && technique.environment_lights_max)
        lights += static_cast<u64>(std::max(0, technique.environment_lights_max(params)));
    std::vector<MemoryTerm> out;
    // G-buffer 56 (position 16 and the geometric normal 8 of it), beauty and visibility 20, per
    // light a visibility layer 16 and diagnostics 16; the readback and the EXR image about 17 float
    // channels each.
    out.push_back({"image.width", "the G-buffer position texture", product({pixels, 16}), true});
    out.push_back({"image.width", "the G-buffer and shading targets", product({pixels, 40 + 20})});
    out.push_back({"image.width", "the " + std::to_string(lights) + " visibility layers",
                   product({pixels, lights, 16}), true});
    out.push_back({"image.width", "the diagnostic layers", product({pixels, lights, 16})});
    const u64 in_flight = static_cast<u64>(std::max(frames_in_flight, 1));
    out.push_back({"image.width",
                   in_flight > 1 ? "the readbacks and EXR images of " + std::to_string(in_flight) +
                                       " frames in flight"
                                 : "the readback and the EXR image",
                   product({pixels, in_flight, 2 * 17 * 4})});
    if (s.image.samples > 1) {
        const u64 samples = static_cast<u64>(s.image.samples);
        out.push_back({"image.samples",
                       "the sample G-buffer positions (" + std::to_string(samples) + " layers)",
                       product({pixels, samples, 16}), true});
        out.push_back({"image.samples", "the rest of the sample G-buffer",
                       product({pixels, samples, 32 + 1})});
    }
    if (technique.memory)
        for (MemoryTerm& t : technique.memory(params, pixels)) out.push_back(std::move(t));
    return out;
}

void checkMemoryBudget(const scene::Scene& s, const techniques::TechniqueInfo& technique,
                       const Params& params, const gl::ContextInfo* gl, int frames_in_flight) {
    const std::string where = s.path.string() + ": ";
    if (technique.limit_error)
        if (std::string error = technique.limit_error(params); !error.empty())
            throw InputError(where + error);
    const std::vector<MemoryTerm> terms = estimateMemory(s, technique, params, frames_in_flight);
    u64 total = 0;
    const MemoryTerm* largest = nullptr;
    for (const MemoryTerm& t : terms) {
        total = total + t.bytes < total ? UINT64_MAX : total + t.bytes;
        if (!largest || t.bytes > largest->bytes) largest = &t;
        if (gl && gl->software && t.one_texture && t.bytes > kSoftwareTextureLimit)
            throw InputError(where + t.key + ": " + t.what + " needs " + formatBytes(t.bytes) +
                             " in one texture, more than this software rasteriser allows (" +
                             formatBytes(kSoftwareTextureLimit) + ")");
    }
    if (largest && total > memoryLimit())
        throw InputError(where + largest->key + ": the render needs about " + formatBytes(total) +
                         " (" + largest->what + " " + formatBytes(largest->bytes) +
                         "), more than the memory limit of " + formatBytes(memoryLimit()) +
                         " (--memory-limit)");
}

}  // namespace penumbra::app
