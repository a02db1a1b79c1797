// The per-frame timing JSON (schema "penumbra-timing/1"): passes in order with the clock each
// figure came from, min/median/max over --repeat, totals, and technique statistics.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace penumbra::output {

struct PassTiming {
    std::string name;        // e.g. "gbuffer", "shadow_map[3]", "shade"
    std::string clock;       // "gl_timer_query" or "cpu_glfinish"
    std::vector<double> ms;  // one figure per measured repeat
};

struct FrameReport {
    std::string scene;  // scene file path
    int frame = 0;
    std::string technique;
    nlohmann::json params;   // resolved technique parameters
    nlohmann::json backend;  // {"api", "device", "renderer", "version", "vendor"}
    int width = 0, height = 0;
    int samples = 1;  // image.samples
    int warmup = 0;
    std::vector<PassTiming> passes;  // in first-run order
    std::vector<double> frame_ms;    // whole frame, per repeat
    // What the process spent before its first pass and how its GL programs were made: the
    // same in every frame of one process ("ms_to_first_pass", "programs_compiled",
    // "programs_from_cache"); left out when empty.
    nlohmann::json process = nlohmann::json::object();
    nlohmann::json stats = nlohmann::json::object();   // technique statistics
    nlohmann::json output = nlohmann::json::object();  // paths written
};

// Median, min and max of a non-empty list.
struct Summary {
    double min = 0, median = 0, max = 0;
};
Summary summarize(std::vector<double> values);

nlohmann::json toJson(const FrameReport& report);
// Writes the report atomically (temporary name, then rename). Throws RuntimeError.
void writeTimingJson(const std::filesystem::path& path, const FrameReport& report);

}  // namespace penumbra::output
