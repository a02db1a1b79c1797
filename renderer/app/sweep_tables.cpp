// The sweep's tables: see sweep_tables.h.
#include "renderer/app/sweep_tables.h"

#include <algorithm>
#include <sstream>
#include <vector>

namespace penumbra::app {

using nlohmann::json;

json metricsJson(const output::CompareResult& r) {
    json m = {{"mae", r.mae},
              {"rmse", r.rmse},
              {"max", r.max},
              {"p99", r.p99},
              {"fail_fraction", r.fail_fraction},
              {"shadow_mae", r.shadow_mae ? json(*r.shadow_mae) : json(nullptr)},
              {"shadow_pixels", r.shadow_pixels ? json(*r.shadow_pixels) : json(0)}};
    return m;
}

json sweepJson(const SweepRequest& req, const SweepPlan& plan, const json& runs,
               const json& backend) {
    json varied = json::array();
    for (const auto& a : req.axes)
        varied.push_back(
            {{"key", a.key}, {"values", a.values}, {"scale", a.log_scale ? "log" : "linear"}});
    json ref_overrides = json::object();
    for (const auto& o : req.reference_sets) ref_overrides[o.key] = o.value;
    const SweepRender& first = plan.runs.front();
    return {{"schema", "penumbra-sweep"},
            {"schema_version", 1},
            {"scene", req.scene.string()},
            {"technique", first.technique_name},
            {"size", {first.width, first.height}},
            {"frame", req.frame},
            {"varied", varied},
            {"reference", {{"technique", req.reference_technique}, {"overrides", ref_overrides}}},
            {"backend", backend},
            {"runs", runs}};
}

namespace {

std::string csvCell(const json& v) {
    std::string s = v.is_string() ? v.get<std::string>() : v.dump();
    if (s.find_first_of(",\"\n") == std::string::npos) return s;
    std::string q = "\"";
    for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
    return q + "\"";
}

}  // namespace

std::string toCsv(const json& sweep) {
    std::vector<std::string> keys;
    for (const auto& a : sweep["varied"]) keys.push_back(a["key"]);
    std::vector<std::string> metrics = {"mae",        "rmse",          "max",          "p99",
                                        "shadow_mae", "shadow_pixels", "fail_fraction"};
    std::vector<std::string> passes, stats;
    for (const auto& r : sweep["runs"]) {
        for (const auto& [k, v] : r["time_ms"]["passes"].items())
            if (std::find(passes.begin(), passes.end(), k) == passes.end()) passes.push_back(k);
        for (const auto& [k, v] : r["stats"].items())
            if (std::find(stats.begin(), stats.end(), k) == stats.end()) stats.push_back(k);
    }
    std::ostringstream out;
    out << "id,technique";
    for (const auto& k : keys) out << "," << csvCell(k);
    out << ",total_ms,total_ms_min,total_ms_max";
    for (const auto& p : passes) out << "," << csvCell(p + "_ms");
    for (const auto& m : metrics) out << "," << m;
    for (const auto& s : stats) out << "," << csvCell(s);
    out << ",exr\n";
    for (const auto& r : sweep["runs"]) {
        out << csvCell(r["id"]) << "," << csvCell(r["technique"]);
        for (const auto& k : keys) out << "," << csvCell(r["values"][k]);
        for (const char* k : {"total", "total_min", "total_max"})
            out << "," << r["time_ms"].value(k, json(nullptr)).dump();
        for (const auto& p : passes)
            out << "," << r["time_ms"]["passes"].value(p, json(nullptr)).dump();
        for (const auto& m : metrics) out << "," << r["metrics"].value(m, json(nullptr)).dump();
        for (const auto& s : stats) out << "," << csvCell(r["stats"].value(s, json(nullptr)));
        out << "," << csvCell(r["exr"]) << "\n";
    }
    return out.str();
}

}  // namespace penumbra::app
