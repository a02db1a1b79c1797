// `penumbra compare`'s command line: the help text and the flag parser (see compare_args.h).
#include "cli/compare_args.h"

#include <cctype>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "cli/commands.h"
#include "renderer/core/error.h"
#include "renderer/core/json_bounds.h"
#include "renderer/core/output_paths.h"

namespace penumbra::cli {

const char* const kCompareUsage = R"(usage: penumbra compare REF.exr TEST.exr [options]

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

namespace {

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

}  // namespace

CompareArgs parseCompareArgs(const Args& args) {
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
    // A CI job's --diff onto its golden image replaced the golden with the difference.
    for (const auto& [name, input] : {std::pair{"REF", a.ref}, std::pair{"TEST", a.test}})
        if (!a.diff.empty() && namesAnyOf(a.diff, {input}))
            c.fail("--diff: '" + quoteText(a.diff) + "' is " + name +
                   "; writing the difference there would overwrite it (name another file)");
    return a;
}

}  // namespace penumbra::cli
