// What ssm allocates and the work one frame's splat may take, checked before a render: see
// ssm.h (memoryTerms, splatLimitError).
#include <cstdint>
#include <string>

#include "glsl/techniques/ssm/bindings.glsl"
#include "renderer/core/memory_limit.h"
#include "renderer/techniques/ssm/ssm.h"

namespace penumbra::techniques::ssm {

MemoryTerms memoryTerms(const Params& p, std::uint64_t) {
    using u64 = std::uint64_t;
    const int ssm = p.get(kSsmSize);
    const auto m = static_cast<u64>(p.get(kMapSize));
    const auto s = static_cast<u64>(ssm);
    const bool two_sided = p.get(kTwoSided);
    const bool samples = p.getEnum(kAccumulate) == Accumulate::Samples;
    const auto sides = static_cast<u64>(
        occluderMapCount(two_sided, samples, p.getEnum(kFarSide) == FarSide::Second));
    // Per receiver layer and texel: the soft shadow maps, and with accumulate=samples the masks
    const u64 soft = 4 * static_cast<u64>(softMapCount(two_sided, samples)) +
                     (samples ? 4 * SSM_SAMPLE_WORDS : 0);
    const auto layers = static_cast<u64>(p.get(kLayers));
    MemoryTerms out;
    // Per occluder texel and side: depth, id, list entry; with `lod` one pyramid (16 bytes,
    // 4/3 with its levels), the merged map (16 bytes) and its slopes (8), shared by the sides.
    const u64 lod = p.get(kLod) > 0.0 ? 46 : 0;
    out.push_back({"technique.map_size", "the occluder maps, their ids and micro-patch lists",
                   saturatingProduct({m, m, (4 + 4 + sizeof(MicroPatch)) * sides + lod})});
    // Per receiver layer: soft shadow maps (per side) or the sample masks, depth and id, the
    // farthest-receiver pyramid (4/3 of a float), the tangent planes (RGBA16F) and the splat's
    // depth and stencil (4); plus the k-buffer's slots and the peeling's scratch depth and ids
    // (its fallback).
    const auto slots = static_cast<u64>(ReceiverLayers::kbufferSlots(static_cast<int>(layers)));
    out.push_back({"technique.layers",
                   "the soft shadow maps and receiver layers (" + squareText(ssm) + " x " +
                       std::to_string(layers) + ")",
                   saturatingProduct({s, s, (soft + 4 + 4 + 6 + 8 + 4) * layers + 4 * slots + 8})});
    return out;
}

std::string splatLimitError(const Params& p) {
    const auto map = static_cast<std::uint64_t>(p.get(kMapSize));
    const auto ssm = static_cast<std::uint64_t>(p.get(kSsmSize));
    if (map * ssm <= kMaxSplatProduct) return {};
    return "technique.ssm_size: map_size x ssm_size = " + std::to_string(map) + " x " +
           std::to_string(ssm) + " exceeds the splat-work bound of " +
           std::to_string(kMaxSplatProduct) + " (2^21)";
}

}  // namespace penumbra::techniques::ssm
