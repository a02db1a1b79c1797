// A sweep's result tables: the run entries' compare metrics, DIR/sweep.json (schema
// "penumbra-sweep") and the same as CSV, one row a run.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "renderer/app/sweep_plan.h"
#include "renderer/output/compare.h"

namespace penumbra::app {

// The compare metrics of a run entry (mae, rmse, max, p99, fail_fraction, shadow_*).
nlohmann::json metricsJson(const output::CompareResult& r);

// sweep.json: the sweep's settings, BACKEND and the run entries RUNS.
nlohmann::json sweepJson(const SweepRequest& req, const SweepPlan& plan, const nlohmann::json& runs,
                         const nlohmann::json& backend);

// sweep.csv of SWEEP (sweepJson's result): id, technique, varied values, times, metrics,
// statistics, EXR path.
std::string toCsv(const nlohmann::json& sweep);

}  // namespace penumbra::app
