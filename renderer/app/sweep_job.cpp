// The sweep job: see sweep_job.h. Its steps: plan (sweep_plan.h), references, runs, tables
// (sweep_tables.h) and report (sweep_processes.h).
#include "renderer/app/sweep_job.h"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <map>
#include <memory>
#include <regex>

#include "renderer/app/sweep_plan.h"
#include "renderer/app/sweep_processes.h"
#include "renderer/app/sweep_tables.h"
#include "renderer/core/atomic_file.h"
#include "renderer/core/error.h"
#include "renderer/frame/render_frame.h"
#include "renderer/gl/debug.h"
#include "renderer/output/compare.h"
#include "renderer/output/exr.h"
#include "renderer/output/heatmap.h"
#include "renderer/output/preview.h"
#include "renderer/output/timing.h"
#include "renderer/scene/json_file.h"
#include "renderer/techniques/technique.h"

namespace penumbra::app {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

constexpr size_t kMaxRecordBytes = size_t{16} << 20;  // runs/run-NNNN.json, read back on reruns
constexpr float kHeatmapFullScale = 0.25f;            // |dV| of 0.25 or more is drawn white

// A sweep under way: its plan, the context (created when something has to render) and counts.
struct Sweep {
    const SweepRequest& req;
    SweepPlan plan;
    std::unique_ptr<gl::Context> context;
    std::vector<fs::path> ref_paths;  // <cache>/reference-<hash>.exr per reference
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
    json passes = json::object();  // grouped medians: "shadow_maps[3]@1" -> "shadow_maps"
    double total_ms = 0;           // the median over --repeat
    double total_min_ms = 0, total_max_ms = 0;  // its spread
    json stats;
};

// Renders JOB RUNS times; its passes grouped by name without [batch] and @light, medians of the
// timed runs.
Rendered render(const SweepRender& job, Sweep& sweep, frame::FrameRuns runs) {
    const SweepRequest& req = sweep.req;
    scene::LoadOptions options;
    options.technique = job.technique;
    auto source = scene::SceneSource::load(req.scene, job.overrides, options);
    scene::Scene s = source.at(req.frame);
    const auto& info = *techniques::findTechnique(job.technique_name);
    frame::RenderedFrame frame = frame::renderFrame(
        sweep.gl(), s, info, resolveParams(info.params, s.technique, "technique"), runs);
    std::map<std::string, std::vector<double>> grouped;
    std::vector<double> totals;
    static const std::regex suffix(R"((\[\d+\])?(@\d+)?$)");
    for (const frame::TimedRun& run : frame.runs) {
        std::map<std::string, double> sums;
        double total = 0;
        for (const auto& t : run.passes) {
            sums[std::regex_replace(t.name, suffix, "")] += t.ms;
            total += t.ms;
        }
        for (const auto& [k, v] : sums) grouped[k].push_back(v);
        totals.push_back(total);
    }
    Rendered out;
    for (const auto& [k, v] : grouped) out.passes[k] = output::summarize(v).median;
    const output::Summary total = output::summarize(totals);
    out.total_ms = total.median;
    out.total_min_ms = total.min;
    out.total_max_ms = total.max;
    out.stats = std::move(frame.stats);
    out.image = std::move(frame.image);
    out.image.attributes.emplace_back("penumbra/scene", req.scene.string());
    return out;
}

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
        removeStaleTemporaries(path);
        if (sweep.progress)
            std::fprintf(stderr, "penumbra: sweep: reference %zu of %zu\n", i + 1,
                         references.size());
        output::writeExr(path, render(references[i], sweep, {0, 1}).image);
        ++sweep.rendered_refs;
    }
}

// The record of run ID when RECORD holds one for HASH whose EXR is readable, else null.
json reusableRecord(const fs::path& record, const fs::path& out, const std::string& hash) {
    if (!fs::exists(record)) return nullptr;
    try {  // a record that is not this run's (or not a bounded JSON file) is redone
        json old = scene::parseJsonText(
            scene::readTextFile(record, record.string(), kMaxRecordBytes), record.string());
        if (old.is_object() && old.value("settings_hash", "") == hash &&
            output::isReadableExr(out / old.value("exr", std::string("-"))))
            return old;
    } catch (const InputError&) {
    } catch (const json::exception&) {
    }
    return nullptr;
}

// Renders run I (called ID) and writes its EXR, preview, heatmap and record; returns the entry.
json renderRun(Sweep& sweep, size_t i, const std::string& id, const json& values) {
    const SweepRequest& req = sweep.req;
    const SweepRender& run = sweep.plan.runs[i];
    const fs::path& ref_path = sweep.ref_paths[sweep.plan.run_reference[i]];
    output::CompareOptions compare;
    compare.channels = {"visibility"};
    compare.fail = 0.05;  // fail_fraction: share of pixels whose visibility is off by > 0.05
    Rendered r = render(run, sweep, req.runs);
    const std::string base = "runs/" + id;
    output::writeExr(req.out / (base + ".exr"), r.image);
    output::writePngPreview(req.out / (base + ".png"), r.image);
    output::Image ref = output::readExr(ref_path);
    auto result = output::compareImages(ref, r.image, compare);
    output::writeErrorHeatmap(req.out / (base + ".error.png"), ref, r.image, "visibility",
                              kHeatmapFullScale);  // with its colour bar: 0 to the scale
    json entry = {{"id", id},
                  {"values", values},
                  {"technique", run.technique_name},
                  {"settings_hash", run.hash},
                  {"exr", base + ".exr"},
                  {"preview", base + ".png"},
                  {"heatmap", base + ".error.png"},
                  {"heatmap_scale", kHeatmapFullScale},
                  {"reference", referenceEntry(req, ref_path)},
                  {"time_ms",
                   {{"total", r.total_ms},
                    {"total_min", r.total_min_ms},
                    {"total_max", r.total_max_ms},
                    {"passes", r.passes}}},
                  {"metrics", metricsJson(result)},
                  {"stats", r.stats}};
    writeFileAtomically(req.out / "runs" / (id + ".json"), entry.dump(2) + "\n");
    return entry;
}

// 3. The runs, each reused when its files exist for the same settings; their entries.
json renderRuns(Sweep& sweep) {
    const SweepRequest& req = sweep.req;
    json entries = json::array();
    for (size_t i = 0; i < sweep.plan.runs.size(); ++i) {
        if (req.run_index && static_cast<int>(i) + 1 != *req.run_index) continue;
        char id[32];
        std::snprintf(id, sizeof id, "run-%04zu", i + 1);
        json values = json::object();
        for (const auto& [key, value] : sweep.plan.points[i]) values[key] = value;
        json entry = reusableRecord(req.out / "runs" / (std::string(id) + ".json"), req.out,
                                    sweep.plan.runs[i].hash);
        if (entry.is_null()) {
            if (sweep.progress)
                std::fprintf(stderr, "penumbra: sweep: run %zu of %zu %s\n", i + 1,
                             sweep.plan.runs.size(), values.dump().c_str());
            try {
                entry = renderRun(sweep, i, id, values);
                ++sweep.rendered_runs;
            } catch (const RuntimeError& e) {
                std::fprintf(stderr, "penumbra: sweep: %s: %s\n", id, e.what());
                ++sweep.failed;
                continue;
            }
        }
        entries.push_back(entry);
    }
    return entries;
}

}  // namespace

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
