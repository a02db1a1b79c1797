// The processes a sweep starts: its runs as parallel `penumbra sweep --run-index K` jobs
// through GNU parallel, and the report script (scripts/sweep-report) at the end.
#pragma once

#include <cstddef>
#include <filesystem>

#include "renderer/app/sweep_job.h"

namespace penumbra::app {

// Renders runs 1..COUNT as `penumbra sweep ... --run-index K` jobs, REQ.jobs at a time, through
// GNU parallel. False when parallel is missing or a job failed.
bool runParallel(const SweepRequest& req, std::size_t count);

// Runs the report script on DIR: $PENUMBRA_SWEEP_REPORT, else the source tree's
// scripts/sweep-report (a path compiled in). False when it is missing or failed.
bool runReport(const std::filesystem::path& dir, bool quiet);

}  // namespace penumbra::app
