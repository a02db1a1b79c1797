// `penumbra compare REF.exr TEST.exr`: golden-image diff with OpenImageIO idiff's thresholds,
// summary and exit codes (0 pass, 1 warn, 2 fail, 3 cannot compare, 4 file error, 5 usage).
#include <algorithm>
#include <cstdio>
#include <iostream>
#include <string>

#include "cli/args.h"
#include "cli/commands.h"
#include "cli/compare_args.h"
#include "cli/compare_summary.h"
#include "renderer/core/error.h"
#include "renderer/output/compare.h"
#include "renderer/output/exr.h"
#include "renderer/output/heatmap.h"

namespace penumbra::cli {

namespace {

constexpr int kExitMismatch = 3;    // idiff's "different size": cannot compare
constexpr int kExitUnreadable = 4;  // idiff's file error: unreadable input, unwritable --diff
constexpr int kExitUsage = 5;       // bad command line (idiff has none of its own)

// Writes the --diff file: an EXR of the differences, or a PNG heatmap. Returns the scale a
// heatmap used (0 for an EXR). Throws Error.
double writeDiff(const CompareArgs& a, const output::Image& ref, const output::Image& test) {
    output::Image diff = output::differenceImage(ref, test, a.options);
    if (a.diffPng) {
        const double scale = a.diffScale ? *a.diffScale : output::defaultDifferenceScale(diff);
        output::writeDifferenceHeatmap(a.diff, diff, static_cast<float>(scale));
        return scale;
    }
    diff.attributes = {{"penumbra/compare/reference", a.ref}, {"penumbra/compare/test", a.test}};
    output::writeExr(a.diff, diff);
    return 0.0;
}

// The --json object, or the text summary, of RESULT with the --diff file's outcome.
void printResult(const CompareArgs& a, const output::CompareResult& result, bool diffFailed,
                 double diffScale) {
    if (a.json) {
        nlohmann::json j = result.toJson();
        j["reference"] = a.ref;
        j["test"] = a.test;
        if (!a.diff.empty()) j["diff"] = diffFailed ? nlohmann::json() : nlohmann::json(a.diff);
        if (a.diffPng && !diffFailed) j["diff_scale"] = diffScale;
        std::cout << j.dump(2) << std::endl;
    } else {
        printSummary(a, result);
        if (a.diffPng && !diffFailed)
            std::printf("  Heatmap %s: white = %s\n", a.diff.c_str(),
                        formatValue(diffScale).c_str());
        std::fflush(stdout);
    }
}

}  // namespace

int runCompare(const Args& args) {
    for (const auto& a : args)
        if (a == "--help" || a == "-h") {
            std::fputs(kCompareUsage, stdout);
            return 0;
        }
    CompareArgs a;
    try {
        a = parseCompareArgs(args);
    } catch (const InputError& e) {
        const bool json = std::find(args.begin(), args.end(), "--json") != args.end();
        return cannotCompare(json, "", "", kExitUsage, e.what());
    }

    output::Image ref, test;
    try {
        ref = output::readExr(a.ref);
        test = output::readExr(a.test);
    } catch (const output::UnreadableImage& e) {
        return cannotCompare(a.json, a.ref, a.test, kExitUnreadable,
                             std::string("compare: ") + e.what());
    }

    output::CompareResult result;
    try {
        result = output::compareImages(ref, test, a.options);
    } catch (const output::CompareMismatch& e) {
        using Side = output::CompareMismatch::Side;
        const std::string& file = e.side() == Side::Test ? a.test : a.ref;
        const std::string where = e.side() == Side::Both ? a.ref + " vs " + a.test : file;
        return cannotCompare(a.json, a.ref, a.test, kExitMismatch,
                             "compare: " + where + ": " + e.what());
    }

    // The difference image is written even when the comparison fails; a write failure is a
    // file error (exit 4), never mistaken for a verdict.
    bool diffFailed = false;
    double diffScale = 0.0;
    if (!a.diff.empty()) {
        try {
            diffScale = writeDiff(a, ref, test);
        } catch (const Error& e) {
            std::fprintf(stderr, "penumbra: compare: --diff: %s\n", e.what());
            diffFailed = true;
        }
    }

    printResult(a, result, diffFailed, diffScale);
    if (diffFailed) return kExitUnreadable;
    return a.noFail ? 0 : static_cast<int>(result.verdict);
}

}  // namespace penumbra::cli
