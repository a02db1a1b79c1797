// A comparison's result as JSON (compare --json, sweep records): every metric, non-finite ones
// as null, and the thresholds it was judged by.
#include <cmath>
#include <optional>

#include "renderer/output/compare.h"

namespace penumbra::output {
namespace {

nlohmann::json number(double value) {
    return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(nullptr);
}

template <typename T>
nlohmann::json optionalJson(const std::optional<T>& value) {
    return value ? number(static_cast<double>(*value)) : nlohmann::json(nullptr);
}

}  // namespace

const char* verdictName(Verdict verdict) {
    switch (verdict) {
        case Verdict::Pass:
            return "pass";
        case Verdict::Warn:
            return "warn";
        case Verdict::Fail:
            return "fail";
    }
    return "fail";
}

nlohmann::json CompareResult::toJson() const {
    nlohmann::json perChannel = nlohmann::json::array();
    for (const auto& m : per_channel)
        perChannel.push_back({{"name", m.name},
                              {"mae", number(m.mae)},
                              {"rmse", number(m.rmse)},
                              {"max", number(m.max)},
                              {"max_x", m.max_x},
                              {"max_y", m.max_y},
                              {"p99", number(m.p99)},
                              {"nonfinite", m.nonfinite}});
    return {
        {"verdict", verdictName(verdict)},
        {"width", width},
        {"height", height},
        {"pixels", pixels},
        {"channels", channels},
        {"mae", number(mae)},
        {"rmse", number(rmse)},
        {"max", number(max)},
        {"max_x", max_x},
        {"max_y", max_y},
        {"max_channel", max_channel},
        {"p99", number(p99)},
        {"nonfinite", nonfinite},
        {"fail_pixels", fail_pixels},
        {"fail_fraction", fail_fraction},
        {"warn_pixels", warn_pixels},
        {"warn_fraction", warn_fraction},
        {"shadow_mae", optionalJson(shadow_mae)},
        {"shadow_pixels", shadow_pixels ? nlohmann::json(*shadow_pixels) : nlohmann::json()},
        {"thresholds",
         {{"fail", options.fail},
          {"fail_percent", options.fail_percent},
          {"warn", options.warn},
          {"warn_percent", options.warn_percent},
          {"hard_fail", optionalJson(options.hard_fail)}}},
        {"per_channel", perChannel},
    };
}

}  // namespace penumbra::output
