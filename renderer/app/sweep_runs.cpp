// A sweep's runs: each rendered, written (EXR, preview, heatmap, record) and compared with its
// reference, or reused when its record and EXR exist for the same settings.
#include <cstdio>
#include <string>

#include "renderer/app/sweep_state.h"
#include "renderer/app/sweep_tables.h"
#include "renderer/core/atomic_file.h"
#include "renderer/core/error.h"
#include "renderer/output/compare.h"
#include "renderer/output/exr.h"
#include "renderer/output/heatmap.h"
#include "renderer/output/preview.h"
#include "renderer/scene/json_file.h"

namespace penumbra::app {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

constexpr size_t kMaxRecordBytes = size_t{16} << 20;  // runs/run-NNNN.json, read back on reruns
constexpr float kHeatmapFullScale = 0.25f;            // |dV| of 0.25 or more is drawn white

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
    Rendered r = renderTimed(run, sweep, req.runs);
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

}  // namespace

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

}  // namespace penumbra::app
