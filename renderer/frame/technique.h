// The interface a technique implements for the frame layer: a parameter table and a renderer
// of visibility. A technique never times itself, parses JSON or writes files; the frame
// renderer does that around it. Techniques live above (renderer/techniques/, its registry).
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "renderer/core/memory_term.h"
#include "renderer/core/params.h"
#include "renderer/frame/frame_context.h"
#include "renderer/gl/context.h"
#include "renderer/passes/gpu_scene.h"

namespace penumbra::frame {

// A per-pixel diagnostic written to colour 1+i of the output; lights combine by Sum or Max.
struct DiagnosticChannel {
    std::string name;  // written as "<technique>.<name>"
    enum class Combine { Sum, Max } combine = Combine::Max;
};

class Technique {
public:
    virtual ~Technique() = default;
    // Reads the files its parameters name (relative to SCENE's file), once before prepare().
    // Throws InputError naming the parameter.
    virtual void readInputs(const scene::Scene& scene) { (void)scene; }
    // Per-scene resources (maps, programs), once before the first frame.
    virtual void prepare(const gl::ContextInfo& gl, const passes::GpuScene& scene) = 0;
    // Renders visibility (and diagnostics) of ctx.light into ctx.bindOutput()'s targets.
    virtual void render(FrameContext& ctx) = 0;
    virtual std::vector<DiagnosticChannel> diagnostics() const { return {}; }
};

// Lights a technique makes of the scene's environment map, rendered after the scene's own; or,
// with irradiance_layer, one more output layer after them that the technique fills per pixel
// with the environment's shadowed irradiance (rgb) and unshadowed luminance irradiance (a).
// With fold, the lights are rendered a batch at a time into a batch of layers, each batch folded
// by the frame into such an irradiance layer (passes/environment_fold.h): a few layers for any
// number of lights, for a technique without diagnostics.
struct EnvironmentLights {
    std::vector<scene::RectLight> lights;
    bool irradiance_layer = false;
    bool fold = false;
    nlohmann::json stats = nlohmann::json::object();  // e.g. lights fitted, energy captured
};

struct TechniqueInfo {
    std::string_view name;
    std::string_view summary;
    std::span<const ParamSpec> params;  // the one source of truth for -D, JSON, docs, output
    std::unique_ptr<Technique> (*create)(const Params&);
    // The lights of a scene's environment (called only when it has one), or nullptr: the
    // technique ignores environments.
    EnvironmentLights (*environment)(const Params&, const scene::Scene&) = nullptr;
    // The technique's largest allocations for its resolved PARAMS and an image of PIXELS (the
    // memory budget checks them before anything is allocated), or nullptr: none that matter.
    MemoryTerms (*memory)(const Params&, std::uint64_t pixels) = nullptr;
    // A bound the parameter table's ranges cannot say (e.g. a product of two keys): the message
    // "technique.<key>: ..." when PARAMS exceed it, else "". nullptr: none.
    std::string (*limit_error)(const Params&) = nullptr;
    // The most output layers environment() needs for PARAMS (a light each, an irradiance layer
    // one; folded lights a batch and two more): each is a visibility and a diagnostic layer of the
    // frame, which the memory budget counts before anything is allocated. nullptr: none.
    int (*environment_lights_max)(const Params&) = nullptr;
};

}  // namespace penumbra::frame
