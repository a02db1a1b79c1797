// `penumbra sweep SCENE.json --vary ... -o DIR`: argv -> SweepRequest.
#include <cstdio>

#include "cli/backend_flags.h"
#include "cli/commands.h"
#include "cli/run_flags.h"
#include "renderer/app/sweep_job.h"
#include "renderer/core/json_bounds.h"

namespace penumbra::cli {
namespace {

constexpr const char* kHelp =
    R"(usage: penumbra sweep SCENE.json --vary KEY=VALUES [--vary ...] -o DIR [options]

Renders the cartesian product of the varied values with one technique, compares every run
with a reference (rendered once per distinct setting that changes the image, cached by a hash
of everything that determines it in a cache shared by sweeps), and writes DIR/sweep.csv,
DIR/sweep.json, each run's EXR, preview and error heatmap (DIR/runs/), and the report
DIR/index.html with its plots (scripts/sweep-report). A rerun reuses finished runs.

  --vary KEY=V1,V2,...     values (JSON; a bare word is a string): technique.pcf=1,3,5,
                           lights.0.size=[0.5,0.5],[1,1]
  --vary KEY=A:B:N[:log]   N values from A to B, evenly or geometrically spaced
  -t, --technique NAME     the technique under test (default: the scene's)
  -D, --set KEY=VALUE      a fixed override for every run, and for the reference unless it is
                           a technique.* key of another technique than the reference's
  --reference-technique T  the ground truth (default: exact, ray-traced)
  --reference-set K=V      an override for the reference only (default technique.samples=32)
  -f, --frame N            the frame to render (default 0)
  --size WxH               image size
  --warmup N, --repeat N   timing: untimed renders, then the median of N (default 1, 3;
                           at most 100 each)
  -o, --output DIR         where everything goes (required)
  --cache DIR              where references are cached, shared by sweeps (default
                           $XDG_CACHE_HOME/penumbra/references, else
                           ~/.cache/penumbra/references); `--cache none`: DIR/cache
  -j, --jobs N             render the runs as N parallel processes through GNU parallel
                           (timings then compete for the machine: compare them with care)
  --no-report              skip the plots and index.html
  --memory-limit SIZE      refuse runs whose buffers would need more (8G, 512M; default half
                           the physical memory)
  --backend B, --device N, --gl-debug, --quiet   as for render

exit codes: 0 done, 1 a run or the report failed, 2 bad command line or input (found before
anything renders), 3 no usable OpenGL backend.
)";

scene::Override keyValue(const ArgCursor& c, const char* flag, const std::string& v) {
    size_t eq = v.find('=');
    if (eq == std::string::npos || eq == 0)
        c.fail(std::string(flag) + ": expected KEY=VALUE, got '" + quoteText(v) + "'");
    return {v.substr(0, eq), v.substr(eq + 1)};
}

}  // namespace

int runSweep(const Args& args) {
    ArgCursor c("sweep", args);
    app::SweepRequest req;
    req.reference_sets.push_back({"technique.samples", "32"});
    std::optional<std::string> scene, out, cache;
    while (!c.done()) {
        if (c.flag("-h", "--help")) {
            std::fputs(kHelp, stdout);
            return 0;
        }
        std::optional<std::string> v;
        if ((v = c.option("", "--vary"))) {
            req.axes.push_back(parseVary(*v));
        } else if ((v = c.option("-t", "--technique"))) {
            req.technique = *v;
        } else if ((v = c.option("-D", "--set"))) {
            req.overrides.push_back(keyValue(c, "-D", *v));
        } else if ((v = c.option("", "--reference-technique"))) {
            req.reference_technique = *v;
        } else if ((v = c.option("", "--reference-set"))) {
            req.reference_sets.push_back(keyValue(c, "--reference-set", *v));
        } else if ((v = c.option("-f", "--frame"))) {
            req.frame = parseInt(c, "--frame", *v, -10'000'000, 10'000'000);
        } else if (parseRunFlag(c, req.overrides, req.runs)) {
        } else if ((v = c.option("-o", "--output"))) {
            if (v->empty()) c.fail("--output: empty folder name");
            out = *v;
        } else if ((v = c.option("", "--cache"))) {
            if (v->empty()) c.fail("--cache: empty folder name (`--cache none`: DIR/cache)");
            cache = *v;
        } else if ((v = c.option("-j", "--jobs"))) {
            req.jobs = parseInt(c, "--jobs", *v, 1, 256);
        } else if ((v = c.option("", "--run-index"))) {
            req.run_index = parseInt(c, "--run-index", *v, 1, 1'000'000);
        } else if (c.flag("", "--no-report")) {
            req.report = false;
        } else if (c.flag("-q", "--quiet")) {
            req.quiet = true;
        } else if (parseBackendFlag(c, req.gl) || parseMemoryLimitFlag(c)) {
        } else if ((v = c.positional())) {
            if (scene) c.fail("unexpected argument '" + quoteText(*v) + "': one scene per sweep");
            scene = *v;
        } else {
            c.unknown();
        }
    }
    if (!scene) c.fail("missing SCENE.json (see --help)");
    if (!out) c.fail("missing -o DIR");
    if (req.axes.empty()) c.fail("nothing to vary: give at least one --vary KEY=VALUES");
    req.scene = *scene;
    req.out = *out;
    if (!cache)
        req.cache = app::sweepCacheDefault();
    else if (*cache != "none")
        req.cache = *cache;
    // The arguments of each parallel job: these, less --jobs.
    for (size_t i = 0; i < args.size(); ++i) {
        if (args[i] == "-j" || args[i] == "--jobs") {
            ++i;
            continue;
        }
        if (args[i].rfind("--jobs=", 0) == 0) continue;
        req.job_args.push_back(args[i]);
    }
    return app::runSweepJob(req);
}

}  // namespace penumbra::cli
