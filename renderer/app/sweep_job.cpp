// The sweep job: see sweep_job.h. Its steps: plan (sweep_plan.h), references
// (sweep_references.cpp), runs (sweep_runs.cpp), tables (sweep_tables.h), report
// (sweep_processes.h).
#include "renderer/app/sweep_job.h"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>

#include "renderer/app/sweep_plan.h"
#include "renderer/app/sweep_processes.h"
#include "renderer/app/sweep_state.h"
#include "renderer/app/sweep_tables.h"
#include "renderer/core/atomic_file.h"
#include "renderer/core/error.h"

namespace penumbra::app {

namespace fs = std::filesystem;
using nlohmann::json;

fs::path sweepCacheDefault() {
    // XDG Base Directory: a relative $XDG_CACHE_HOME is ignored.
    if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg == '/')
        return fs::path(xdg) / "penumbra" / "references";
    if (const char* home = std::getenv("HOME"); home && *home == '/')
        return fs::path(home) / ".cache" / "penumbra" / "references";
    return {};
}

int runSweepJob(const SweepRequest& req) {
    // 1. Every run and every reference, validated before anything renders.
    Sweep sweep{req, planSweep(req)};
    sweep.progress = !req.quiet && isatty(STDERR_FILENO);
    std::error_code ec;
    fs::create_directories(cacheFolder(req), ec);
    if (ec && !req.cache.empty())  // before anything renders: bad input, exit 2
        throw InputError("--cache: " + req.cache.string() + ": cannot create folder: " +
                         ec.message() + " (--cache none keeps references in DIR/cache)");
    if (ec) throw RuntimeError(req.out.string() + ": cannot create folder: " + ec.message());
    fs::create_directories(req.out / "runs", ec);
    if (ec) throw RuntimeError(req.out.string() + ": cannot create folder: " + ec.message());
    renderReferences(sweep);                 // 2.
    const json entries = renderRuns(sweep);  // 3.
    if (req.run_index) return sweep.failed ? static_cast<int>(ExitCode::RuntimeFailure) : 0;

    // 4. The tables, then the report.
    const json table = sweepJson(req, sweep.plan, entries, sweep.gl().toJson());
    writeFileAtomically(req.out / "sweep.json", table.dump(2) + "\n");
    writeFileAtomically(req.out / "sweep.csv", toCsv(table));
    const int rendered = sweep.rendered_runs + sweep.rendered_by_jobs;
    if (!req.quiet)
        std::fprintf(stderr,
                     "penumbra: sweep: %zu runs (%d rendered, %zu reused, %d failed), %zu "
                     "references (%d rendered); %s\n",
                     sweep.plan.runs.size(), rendered, entries.size() - size_t(rendered),
                     sweep.failed, sweep.plan.references.size(), sweep.rendered_refs,
                     (req.out / "sweep.json").c_str());
    if (req.report && !runReport(req.out, req.quiet)) {
        std::fprintf(stderr, "penumbra: sweep: the report failed\n");
        return static_cast<int>(ExitCode::RuntimeFailure);
    }
    return sweep.failed ? static_cast<int>(ExitCode::RuntimeFailure) : 0;
}

}  // namespace penumbra::app
