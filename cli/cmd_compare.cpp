// `penumbra compare REF.exr TEST.exr`: golden-image diff with OpenImageIO idiff's thresholds,
// summary and exit codes (0 pass, 1 warn, 2 fail, 3 cannot compare, 4 file error, 5 usage).
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <optional>
#include <set>
#include <string>

#include "cli/args.h"
#include "cli/commands.h"
#include "renderer/core/error.h"
#include "renderer/core/json_bounds.h"
#include "renderer/output/compare.h"
#include "renderer/output/exr.h"
#include "renderer/output/heatmap.h"

namespace penumbra::cli {

namespace {

constexpr int kExitMismatch = 3;    // idiff's "different size": cannot compare
constexpr int kExitUnreadable = 4;  // idiff's file error: unreadable input, unwritable --diff
constexpr int kExitUsage = 5;       // bad command line (idiff has none of its own)

constexpr const char* kCompareUsage = R"(usage: penumbra compare REF.exr TEST.exr [options]

Compares TEST against the reference REF like OpenImageIO's idiff. A pixel fails when any
compared channel differs by more than --fail; the result is FAILURE when more than
--failpercent % of the pixels fail or any difference exceeds --hardfail, else WARNING by the
same rule with --warn and --warnpercent, else PASS. NaN, or inf in one image but not the same inf in the other, always fails (the background's
Z = +inf equals itself).

options:
  --fail A           per-channel difference a pixel may have before it fails (default 1e-6)
  --failpercent P    % of pixels allowed to fail (default 0)
  --warn A           per-channel difference before a pixel warns (default 1e-6)
  --warnpercent P    % of pixels allowed to warn (default 0)
  --hardfail A       any difference above A fails outright (default: none)
  --channels C,C,..  channels to compare, e.g. R,G,B or visibility (default: all of REF's)
  --ids N,N,..       compare only pixels whose `id` in REF (the object's index in the scene's
                     `objects`) is listed, e.g. the receivers; counts and means are over them;
                     ids that select no pixel cannot be compared (exit 3)
  --diff OUT.exr     write |REF - TEST| of the compared channels (written even on failure)
  --diff OUT.png     write a heatmap of the largest difference per pixel with a colour bar
                     below it (left 0, right the scale)
  --diff-scale K     the difference that maps to white in a .png diff (default: the largest
                     finite difference)
  --json             print only a JSON object on stdout: every metric, or an `error` field
                     (and `exit`) when it cannot compare
  --no-fail          metrics only: exit 0 whatever the verdict, unless it cannot compare
  --memory-limit SIZE  refuse images whose pixels would need more (8G, 512M; default half
                     the physical memory); exit 4
  --help             print this help
  (idiff's spellings -fail, -failpercent, -warn, -warnpercent, -hardfail also work)

exit status (0-4 as idiff's): 0 pass, 1 warning, 2 failure, 3 cannot compare (size or
channel mismatch, --ids selecting no pixel), 4 file error (unreadable input, --diff not
written), 5 bad command line. With --no-fail, 1 and 2 become 0.
)";

struct CompareArgs {
    std::string ref, test;
    output::CompareOptions options;
    std::string diff;
    bool diffPng = false;             // --diff ends in .png: a heatmap, else an EXR
    std::optional<double> diffScale;  // --diff-scale
    bool json = false;
    bool noFail = false;
};

// True when PATH ends in EXT, ignoring case (EXT is lower case, with its dot).
bool hasExtension(const std::string& path, const std::string& ext) {
    if (path.size() < ext.size()) return false;
    for (size_t i = 0; i < ext.size(); ++i)
        if (std::tolower(static_cast<unsigned char>(path[path.size() - ext.size() + i])) != ext[i])
            return false;
    return true;
}

double parseThreshold(const ArgCursor& c, std::string_view flag, const std::string& text) {
    const double v = parseDouble(c, flag, text);
    if (v < 0) c.fail(std::string(flag) + ": must be >= 0, got '" + quoteText(text) + "'");
    return v;
}

double parsePercent(const ArgCursor& c, std::string_view flag, const std::string& text) {
    const double v = parseDouble(c, flag, text);
    if (v < 0 || v > 100)
        c.fail(std::string(flag) + ": must be in [0, 100], got '" + quoteText(text) + "'");
    return v;
}

// The comma-separated items of FLAG's TEXT, each non-empty and listed once; WHAT names one.
std::vector<std::string> parseList(const ArgCursor& c, const std::string& flag,
                                   const std::string& what, const std::string& text) {
    std::vector<std::string> items;
    std::set<std::string> seen;
    size_t start = 0;
    while (true) {
        const size_t comma = text.find(',', start);
        std::string item =
            text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
        if (item.empty()) c.fail(flag + ": empty " + what + " in '" + quoteText(text) + "'");
        if (!seen.insert(item).second)
            c.fail(flag + ": " + what + " '" + quoteText(item) + "' is listed twice");
        items.push_back(std::move(item));
        if (comma == std::string::npos) break;
        start = comma + 1;
    }
    return items;
}

CompareArgs parseArgs(const Args& args) {
    ArgCursor c("compare", args);
    CompareArgs a;
    std::vector<std::string> files;
    std::optional<std::string> v;
    while (!c.done()) {
        if ((v = c.option("-fail", "--fail"))) {
            a.options.fail = parseThreshold(c, "--fail", *v);
        } else if ((v = c.option("-failpercent", "--failpercent"))) {
            a.options.fail_percent = parsePercent(c, "--failpercent", *v);
        } else if ((v = c.option("-warn", "--warn"))) {
            a.options.warn = parseThreshold(c, "--warn", *v);
        } else if ((v = c.option("-warnpercent", "--warnpercent"))) {
            a.options.warn_percent = parsePercent(c, "--warnpercent", *v);
        } else if ((v = c.option("-hardfail", "--hardfail"))) {
            a.options.hard_fail = parseThreshold(c, "--hardfail", *v);
        } else if ((v = c.option("", "--channels"))) {
            a.options.channels = parseList(c, "--channels", "channel name", *v);
        } else if ((v = c.option("", "--ids"))) {
            a.options.ids.clear();
            for (const auto& id : parseList(c, "--ids", "object index", *v))
                a.options.ids.push_back(parseInt(c, "--ids", id, 0, 1 << 30));
        } else if ((v = c.option("", "--diff"))) {
            if (v->empty()) c.fail("--diff: expected a file name");
            if (!hasExtension(*v, ".exr") && !hasExtension(*v, ".png"))
                c.fail("--diff: '" + quoteText(*v) + "' must end in .exr or .png");
            a.diff = *v;
            a.diffPng = hasExtension(*v, ".png");
        } else if ((v = c.option("", "--diff-scale"))) {
            a.diffScale = parseDouble(c, "--diff-scale", *v);
            if (!(*a.diffScale > 0))
                c.fail("--diff-scale: must be > 0, got '" + quoteText(*v) + "'");
        } else if (c.flag("", "--json")) {
            a.json = true;
        } else if (c.flag("", "--no-fail")) {
            a.noFail = true;
        } else if (parseMemoryLimitFlag(c)) {
        } else if (auto p = c.positional()) {
            if (files.size() == 2)
                c.fail("unexpected argument '" + quoteText(*p) + "' (see --help)");
            files.push_back(*p);
        } else {
            c.unknown();
        }
    }
    if (files.size() != 2) c.fail("expected REF.exr and TEST.exr (see --help)");
    if (a.diffScale && !a.diffPng) c.fail("--diff-scale: needs a --diff OUT.png");
    a.ref = files[0];
    a.test = files[1];
    return a;
}

std::string formatValue(double v) {
    if (std::isinf(v)) return "inf";
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

void printSummary(const CompareArgs& a, const output::CompareResult& r) {
    const long pixels = r.pixels;
    std::string channels;
    for (const auto& name : r.channels) channels += (channels.empty() ? "" : ",") + name;
    std::printf("Comparing \"%s\" and \"%s\" (%dx%d, channels %s)\n", a.ref.c_str(), a.test.c_str(),
                r.width, r.height, channels.c_str());
    if (!r.options.ids.empty())
        std::printf("  %ld pixels of the objects listed by --ids\n", r.pixels);
    std::printf("  Mean error = %s\n", formatValue(r.mae).c_str());
    std::printf("  RMS error = %s\n", formatValue(r.rmse).c_str());
    std::printf("  Max error = %s @ (%d, %d, %s)\n", formatValue(r.max).c_str(), r.max_x, r.max_y,
                r.max_channel.c_str());
    std::printf("  99th percentile error = %s\n", formatValue(r.p99).c_str());
    if (r.nonfinite > 0)
        std::printf("  %ld samples are NaN or inf (counted as infinite differences)\n",
                    r.nonfinite);
    if (r.shadow_pixels) {
        if (r.shadow_mae)
            std::printf("  Shadow-region MAE (visibility < %g) = %s over %ld pixels\n",
                        output::kShadowVisibility, formatValue(*r.shadow_mae).c_str(),
                        *r.shadow_pixels);
        else
            std::printf("  Shadow-region MAE: no pixel has visibility < %g in either image\n",
                        output::kShadowVisibility);
    }
    std::printf("  %ld pixels (%.3g%%) over %s (fail)\n", r.fail_pixels,
                pixels ? 100.0 * r.fail_fraction : 0.0, formatValue(r.options.fail).c_str());
    std::printf("  %ld pixels (%.3g%%) over %s (warn)\n", r.warn_pixels,
                pixels ? 100.0 * r.warn_fraction : 0.0, formatValue(r.options.warn).c_str());
    if (r.options.hard_fail && r.max > *r.options.hard_fail)
        std::printf("  Max error exceeds --hardfail %s\n",
                    formatValue(*r.options.hard_fail).c_str());
    switch (r.verdict) {
        case output::Verdict::Pass:
            std::printf("PASS\n");
            break;
        case output::Verdict::Warn:
            std::printf("WARNING\n");
            break;
        case output::Verdict::Fail:
            std::printf("FAILURE\n");
            break;
    }
}

// When compare cannot compare: the one line MESSAGE on stderr and, with --json, a JSON object
// holding it as `error` on stdout. Returns CODE.
int cannotCompare(bool json, const std::string& ref, const std::string& test, int code,
                  const std::string& message) {
    std::fprintf(stderr, "penumbra: %s\n", message.c_str());
    if (json) {
        nlohmann::json j = {{"error", message}, {"exit", code}};
        if (!ref.empty()) j["reference"] = ref;
        if (!test.empty()) j["test"] = test;
        std::cout << j.dump(2) << std::endl;
    }
    return code;
}

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

}  // namespace

int runCompare(const Args& args) {
    for (const auto& a : args)
        if (a == "--help" || a == "-h") {
            std::fputs(kCompareUsage, stdout);
            return 0;
        }
    CompareArgs a;
    try {
        a = parseArgs(args);
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
    if (diffFailed) return kExitUnreadable;
    return a.noFail ? 0 : static_cast<int>(result.verdict);
}

}  // namespace penumbra::cli
