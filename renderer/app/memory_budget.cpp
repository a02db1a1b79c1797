// Estimates of a render's buffers: see memory_budget.h. Sizes follow the passes' allocations
// (passes/gbuffer.cpp, sample_gbuffer.cpp, shade.cpp, frame/output_targets.cpp and each
// technique's).
#include "renderer/app/memory_budget.h"

#include <algorithm>
#include <cstdint>

#include "renderer/core/error.h"
#include "renderer/core/memory_limit.h"
#include "renderer/techniques/css/css_settings.h"

namespace penumbra::app {
namespace {

using u64 = std::uint64_t;

u64 product(std::initializer_list<u64> f) {
    return saturatingProduct(f);
}

int intOr(const Params& p, const char* key, int fallback) {
    const auto& j = p.json();
    const auto it = j.find(key);
    return it != j.end() && it->is_number_integer() ? it->get<int>() : fallback;
}

std::string square(int size) {
    return std::to_string(size) + "^2";
}

// Each technique's own terms (hard, reference, adaptive, ssm, bitmask, css, exact) for an
// image of PIXELS.
void techniqueTerms(std::string_view t, const Params& p, u64 pixels, std::vector<MemoryTerm>& out) {
    const int map = intOr(p, "map_size", 0);
    const u64 m = static_cast<u64>(map);
    if (t == "hard") {
        out.push_back({"technique.map_size", "the shadow map (" + square(map) + ")",
                       product({m, m, 4}), true});
    } else if (t == "reference") {
        const int n = intOr(p, "samples", 1);
        const int layers = std::min(intOr(p, "batch", 32), std::max(n * n, 1));
        out.push_back(
            {"technique.map_size",
             "the shadow map array (" + square(map) + " x " + std::to_string(layers) + ")",
             product({m, m, 4, static_cast<u64>(layers)}), true});
    } else if (t == "adaptive") {
        const int maps = intOr(p, "max_maps", 81);
        const int layers = maps + std::min(16, maps);  // the maps and the scratch batch
        out.push_back({"technique.map_size",
                       "the shadow map array (" + square(map) + " x " + std::to_string(maps) + ")",
                       product({m, m, 4, static_cast<u64>(maps)}), true});
        out.push_back({"technique.map_size", "the scratch maps",
                       product({m, m, 4, static_cast<u64>(layers - maps)}), true});
        out.push_back({"technique.map_size", "the light-view G-buffer", product({m, m, 48})});
    } else if (t == "ssm") {
        const int ssm = intOr(p, "ssm_size", 256);
        const u64 s = static_cast<u64>(ssm);
        const u64 sides = p.json().value("two_sided", false) ? 2 : 1;
        const u64 layers = static_cast<u64>(intOr(p, "layers", 4));
        out.push_back({"technique.map_size", "the occluder maps, their ids and micro-patch lists",
                       product({m, m, 4 + 4 + 8, sides})});
        // Per receiver layer: soft shadow maps (per side), depth and id, the farthest-receiver
        // pyramid (4/3 of a float); plus the peeling's scratch depth and ids.
        out.push_back({"technique.layers",
                       "the soft shadow maps and receiver layers (" + square(ssm) + " x " +
                           std::to_string(layers) + ")",
                       product({s, s, (4 * sides + 4 + 4 + 6) * layers + 8})});
    } else if (t == "bitmask") {
        const u64 ysm = static_cast<u64>(intOr(p, "ysm_size", 256));
        out.push_back({"technique.map_size", "the light depth map and its depth ranges",
                       product({m, m, 4 + 11 + 11})});
        out.push_back({"technique.ysm_size", "the YSM", product({ysm, ysm, 11})});
    } else if (t == "css") {
        const int order = intOr(p, "order", 4);
        const u64 layers = 2 * static_cast<u64>((order + 1) / 2) + 1;
        const bool mipmap = p.json().contains("filter") && p.getEnum(techniques::css::kFilter) !=
                                                               techniques::css::FilterChoice::Sat;
        const u64 basis = product({m, m, 16, layers});
        out.push_back(
            {"technique.order",
             "the basis images (" + square(map) + " x " + std::to_string(layers) + " RGBA32F)",
             mipmap ? basis + basis / 3 : basis, true});
        if (p.json().value("filter", std::string("sat")) != "mipmap")
            out.push_back({"technique.order", "the summed-area tables",
                           product({m + 1, m + 1, 16, layers}), true});
        out.push_back({"technique.map_size", "the shadow map", product({m, m, 4})});
    } else if (t == "exact") {
        // The G-buffer read back (position and normal, 32 bytes a pixel) and the layer it
        // computes (16), on the CPU.
        out.push_back({"image.width", "exact's readback and ray results (48 bytes a pixel)",
                       product({pixels, 48})});
    }
}

}  // namespace

std::vector<MemoryTerm> estimateMemory(const scene::Scene& s, std::string_view technique,
                                       const Params& params, int frames_in_flight) {
    const u64 pixels = product({static_cast<u64>(s.image.width), static_cast<u64>(s.image.height)});
    const u64 lights = std::max<u64>(1, s.lights.size());
    std::vector<MemoryTerm> out;
    // G-buffer 56 (position 16 and the geometric normal 8 of it), beauty and visibility 20, per
    // light a visibility layer 16 and diagnostics 16; the readback and the EXR image about 17 float
    // channels each.
    out.push_back({"image.width", "the G-buffer position texture", product({pixels, 16}), true});
    out.push_back({"image.width", "the G-buffer and shading targets", product({pixels, 40 + 20})});
    out.push_back({"image.width", "the visibility layers", product({pixels, lights, 16}), true});
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
    techniqueTerms(technique, params, pixels, out);
    return out;
}

void checkMemoryBudget(const scene::Scene& s, std::string_view technique, const Params& params,
                       const gl::ContextInfo* gl, int frames_in_flight) {
    const std::string where = s.path.string() + ": ";
    if (technique == "ssm") {
        const u64 map = static_cast<u64>(intOr(params, "map_size", 0));
        const u64 ssm = static_cast<u64>(intOr(params, "ssm_size", 0));
        if (map * ssm > kMaxSsmSplatProduct)
            throw InputError(where +
                             "technique.ssm_size: map_size x ssm_size = " + std::to_string(map) +
                             " x " + std::to_string(ssm) + " exceeds the splat-work bound of " +
                             std::to_string(kMaxSsmSplatProduct) + " (2^21)");
    }
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
    if (gl) {
        for (const char* key : {"ssm_size", "ysm_size"})
            if (intOr(params, key, 0) > gl->max_texture_size)
                throw InputError(
                    where + "technique." + key + ": " + std::to_string(intOr(params, key, 0)) +
                    " exceeds this GL's texture limit of " + std::to_string(gl->max_texture_size));
    }
    if (largest && total > memoryLimit())
        throw InputError(where + largest->key + ": the render needs about " + formatBytes(total) +
                         " (" + largest->what + " " + formatBytes(largest->bytes) +
                         "), more than the memory limit of " + formatBytes(memoryLimit()) +
                         " (--memory-limit)");
}

}  // namespace penumbra::app
