// `penumbra compare`'s command line: its help text and its flags (idiff's thresholds, --channels,
// --ids, --diff, --json, --no-fail), parsed and checked.
#pragma once

#include <optional>
#include <string>

#include "cli/args.h"
#include "cli/commands.h"
#include "renderer/output/compare.h"

namespace penumbra::cli {

extern const char* const kCompareUsage;

struct CompareArgs {
    std::string ref, test;
    output::CompareOptions options;
    std::string diff;
    bool diffPng = false;             // --diff ends in .png: a heatmap, else an EXR
    std::optional<double> diffScale;  // --diff-scale
    bool json = false;
    bool noFail = false;
};

// Parses compare's ARGS; throws InputError naming the flag.
CompareArgs parseCompareArgs(const Args& args);

}  // namespace penumbra::cli
