// Parameter sweeps: `--vary KEY=V1,V2,...`, `KEY=A:B:N` and `KEY=A:B:N:log` parsed into axes of
// JSON values, and the cartesian product of the axes as ordered lists of KEY=VALUE settings.
#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

namespace penumbra {

struct VaryAxis {
    std::string key;  // dotted scene key, as for -D
    std::vector<nlohmann::json> values;
    bool log_scale = false;  // from A:B:N:log
};

// One setting of every axis, in axis order.
using SweepPoint = std::vector<std::pair<std::string, nlohmann::json>>;

// Parses the text after --vary. Values are JSON (a bare word is a string); commas inside
// brackets or quotes do not split. Throws InputError("--vary KEY=...: ...").
VaryAxis parseVary(std::string_view text);

// Every combination, the last axis varying fastest. Throws InputError when there would be more
// than MAX_POINTS or when two axes name the same key.
std::vector<SweepPoint> cartesianProduct(const std::vector<VaryAxis>& axes, size_t max_points);

}  // namespace penumbra
