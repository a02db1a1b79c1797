// The state of a sweep under way, shared by its steps: references (sweep_references.cpp), runs
// (sweep_runs.cpp) and the job (sweep_job.cpp); one timed render (sweep_render.cpp).
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "renderer/app/sweep_job.h"
#include "renderer/app/sweep_plan.h"
#include "renderer/gl/context.h"
#include "renderer/gl/debug.h"
#include "renderer/output/image.h"

namespace penumbra::app {

// A sweep under way: its plan, the context (created when something has to render) and counts.
struct Sweep {
    const SweepRequest& req;
    SweepPlan plan;
    std::unique_ptr<gl::Context> context;
    std::vector<std::filesystem::path> ref_paths;  // <cache>/reference-<hash>.exr per reference
    int rendered_refs = 0, rendered_runs = 0, rendered_by_jobs = 0, failed = 0;
    bool progress = false;  // progress lines only on a terminal

    const gl::ContextInfo& gl() {
        if (!context) {
            context = gl::Context::create(req.gl);
            gl::enableDebugOutput(req.gl.debug);
        }
        return context->info();
    }
};

struct Rendered {
    output::Image image;
    nlohmann::json passes =
        nlohmann::json::object();  // grouped medians: "shadow_maps[3]@1" -> "shadow_maps"
    double total_ms = 0;           // the median over --repeat
    double total_min_ms = 0, total_max_ms = 0;  // its spread
    nlohmann::json stats;
};

// Renders JOB RUNS times; its passes grouped by name without [batch] and @light, medians of the
// timed runs.
Rendered renderTimed(const SweepRender& job, Sweep& sweep, frame::FrameRuns runs);

// Where the references are: the shared cache (--cache), else the sweep's own DIR/cache.
std::filesystem::path cacheFolder(const SweepRequest& req);

// A reference's path as a run entry records it: relative to DIR inside it, else absolute.
std::string referenceEntry(const SweepRequest& req, const std::filesystem::path& path);

// 2. With --jobs, the runs as parallel processes; then the references the cache lacks.
void renderReferences(Sweep& sweep);

// 3. The runs, each reused when its files exist for the same settings; their entries.
nlohmann::json renderRuns(Sweep& sweep);

}  // namespace penumbra::app
