// What a sweep renders, planned and validated before anything renders: one render per point
// of the --vary product and one reference per distinct image-changing setting, each with the
// hash of what determines its image.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "renderer/app/sweep_job.h"

namespace penumbra::app {

// One render to make: its scene settings, validated, and the hash of what determines its image.
struct SweepRender {
    std::vector<scene::Override> overrides;
    std::optional<std::string> technique;
    std::string hash;
    std::string technique_name;
    int width = 0, height = 0;
};

struct SweepPlan {
    std::vector<SweepPoint> points;          // the varied values of each run
    std::vector<SweepRender> runs;           // one per point
    std::vector<SweepRender> references;     // distinct by hash
    std::vector<std::size_t> run_reference;  // per run, its index into references
};

// Every run and reference of REQ, validated (throws InputError: exit 2 before any rendering).
SweepPlan planSweep(const SweepRequest& req);

}  // namespace penumbra::app
