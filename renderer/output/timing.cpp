// Timing JSON: see timing.h.
#include "renderer/output/timing.h"

#include <algorithm>
#include <fstream>

#include "renderer/core/atomic_file.h"

namespace penumbra::output {

Summary summarize(std::vector<double> values) {
    Summary s;
    if (values.empty()) return s;
    std::sort(values.begin(), values.end());
    s.min = values.front();
    s.max = values.back();
    size_t n = values.size();
    s.median = n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
    return s;
}

namespace {
nlohmann::json summaryJson(const std::vector<double>& ms) {
    Summary s = summarize(ms);
    return {{"min", s.min}, {"median", s.median}, {"max", s.max}};
}
}  // namespace

nlohmann::json toJson(const FrameReport& r) {
    nlohmann::json passes = nlohmann::json::array();
    double total = 0;
    for (const auto& p : r.passes) {
        Summary s = summarize(p.ms);
        total += s.median;
        nlohmann::json j = {{"name", p.name}, {"ms", s.median}, {"clock", p.clock}};
        if (p.ms.size() > 1) {
            j["min_ms"] = s.min;
            j["median_ms"] = s.median;
            j["max_ms"] = s.max;
            j["samples_ms"] = p.ms;
        }
        passes.push_back(std::move(j));
    }
    nlohmann::json totals = {{"passes_ms", total},
                             {"frame_ms", summarize(r.frame_ms).median},
                             {"repeats", r.frame_ms.size()},
                             {"warmup", r.warmup}};
    if (r.frame_ms.size() > 1) totals["frame"] = summaryJson(r.frame_ms);
    nlohmann::json out = {
        {"schema", "penumbra-timing"},
        {"schema_version", 1},
        {"scene", r.scene},
        {"frame", r.frame},
        {"technique", r.technique},
        {"params", r.params},
        {"backend", r.backend},
        {"resolution", {{"width", r.width}, {"height", r.height}, {"samples", r.samples}}},
        {"passes", passes},
        {"totals", totals},
        {"stats", r.stats},
        {"output", r.output}};
    if (!r.process.empty()) out["process"] = r.process;
    return out;
}

void writeTimingJson(const std::filesystem::path& path, const FrameReport& report) {
    writeFileAtomically(path, toJson(report).dump(2) + "\n");
}

}  // namespace penumbra::output
