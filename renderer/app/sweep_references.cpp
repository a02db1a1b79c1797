// A sweep's references: where they are cached, how a run entry names one, and rendering the
// ones the cache lacks (after the --jobs processes, which render runs).
#include <cstdio>
#include <string>

#include "renderer/app/sweep_processes.h"
#include "renderer/app/sweep_state.h"
#include "renderer/core/atomic_file.h"
#include "renderer/core/error.h"
#include "renderer/output/exr.h"

namespace penumbra::app {

namespace fs = std::filesystem;

// Where the references are: the shared cache (--cache), else the sweep's own DIR/cache.
fs::path cacheFolder(const SweepRequest& req) {
    return req.cache.empty() ? req.out / "cache" : req.cache;
}

// A reference's path as a run entry records it: relative to DIR inside it, else absolute.
std::string referenceEntry(const SweepRequest& req, const fs::path& path) {
    if (req.cache.empty()) return fs::relative(path, req.out).string();
    std::error_code ec;
    const fs::path absolute = fs::absolute(path, ec);
    return ec ? path.string() : absolute.lexically_normal().string();
}

namespace {

// Number of run records (runs/run-NNNN.json) of the sweep that exist.
int countRecords(const Sweep& sweep) {
    int n = 0;
    for (size_t k = 1; k <= sweep.plan.runs.size(); ++k) {
        char name[40];
        std::snprintf(name, sizeof name, "run-%04zu.json", k);
        n += fs::exists(sweep.req.out / "runs" / name);
    }
    return n;
}

}  // namespace

// 2. With --jobs, the runs as parallel processes; then the references the cache lacks.
void renderReferences(Sweep& sweep) {
    const SweepRequest& req = sweep.req;
    if (req.run_index &&
        (*req.run_index < 1 || *req.run_index > static_cast<int>(sweep.plan.runs.size())))
        throw InputError("--run-index: " + std::to_string(*req.run_index) + " is not a run (1 to " +
                         std::to_string(sweep.plan.runs.size()) + ")");
    if (req.jobs > 1 && !req.run_index) {
        const int before = countRecords(sweep);
        if (!runParallel(req, sweep.plan.runs.size()))
            std::fprintf(stderr,
                         "penumbra: sweep: some parallel runs failed; retrying them here\n");
        sweep.rendered_by_jobs = countRecords(sweep) - before;
    }
    const auto& references = sweep.plan.references;
    for (size_t i = 0; i < references.size(); ++i) {
        fs::path path = cacheFolder(req) / ("reference-" + references[i].hash + ".exr");
        sweep.ref_paths.push_back(path);
        const bool needed = !req.run_index ||
                            sweep.plan.run_reference[static_cast<size_t>(*req.run_index - 1)] == i;
        if (!needed || output::isReadableExr(path)) continue;  // a truncated one is redone
        // Another sweep may be rendering it too: each writes its own temporary and renames it
        // (same pixels), so the last rename wins and no reader sees a partial file.
        penumbra::removeStaleTemporaries(path);
        if (sweep.progress)
            std::fprintf(stderr, "penumbra: sweep: reference %zu of %zu\n", i + 1,
                         references.size());
        output::writeExr(path, renderTimed(references[i], sweep, {0, 1}).image);
        ++sweep.rendered_refs;
    }
}

}  // namespace penumbra::app
