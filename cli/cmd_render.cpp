// `penumbra render SCENE.json|MODEL.glb [options]`: argv -> RenderRequest; no GL, no JSON details
// here.
#include <charconv>
#include <cstdio>
#include <cstdlib>

#include "cli/backend_flags.h"
#include "cli/commands.h"
#include "cli/gltf_flags.h"
#include "cli/run_flags.h"
#include "renderer/app/render_job.h"
#include "renderer/core/json_bounds.h"
#include "renderer/output/exr.h"

namespace penumbra::cli {
namespace {

constexpr const char* kHelp = R"(usage: penumbra render SCENE.json|MODEL.glb [options]

Renders the scene's frames offscreen with one soft-shadow technique and writes, per frame, an
OpenEXR image (beauty, depth, position, normal, visibility, id, diagnostics) and a timing JSON.
A .gltf/.glb is rendered as the scene `penumbra scene` makes of it: its first camera (else one
that frames the model), its KHR_lights_punctual lights (else one light above), and a floor.

options:
  -t, --technique NAME   a technique of `penumbra techniques`; overrides technique.name
  -D, --set KEY=VALUE    override a scene value by dotted path (repeatable); VALUE is JSON,
                         a bare word is a string: -D technique.samples=8 -D lights.0.size=[1,1]
  -o, --output PATTERN   EXR path (.exr); a run of # is the zero-padded frame number, needed
                         with several frames or --frame-from-env (default
                         out/<scene name>.####.exr)
      --timings PATTERN  timing JSON path (default: the EXR path with .json)
      --preview PATTERN  also write a tone-mapped PNG (.png)
      --exr-compression C  zips (the default: zlib, a block per row, level 4; zips:1 to zips:9
                         from fastest to smallest), zip[:LEVEL] (16 rows a block), rle,
                         none or piz; all lossless
  -f, --frames SPEC      7, 1-120, 1-120:4, 1-3,5,9-20:2, frames 0 or more; -f1-3 works too
                         (default: the scene's animation range, else frame 0)
      --frame-from-env VAR  render the one frame named by environment variable VAR (a farm's
                         task index, e.g. SLURM_ARRAY_TASK_ID), plus --frame-offset K
      --frame-offset K   added to --frame-from-env's value (default 0)
      --list-frames      print the frames this command would render, one per line, and exit
      --size WxH         image size (same as -D image.width=W -D image.height=H)
      --light-size W[xH] a glTF's lights as rect lights of this size, metres (default: a
                         quarter of the model's bounding radius; the default light: the radius)
      --no-floor         a glTF: no floor under the model
      --backend B        auto (default), egl (device, then surfaceless), egl-device,
                         egl-surfaceless, osmesa
      --device N         EGL device index (see `penumbra info`)
      --skip-existing    skip frames whose files (EXR, JSON, preview) all exist already
      --strict           a frame outside the scene's animation range is an error, not a
                         warning
      --warmup N         render each frame N extra times first, untimed (0 to 100)
      --repeat N         time N renders per frame (1 to 100); the JSON gets min/median/max
                         per pass
      --quiet            no progress or messages except errors
      --gl-debug         print every KHR_debug message
      --memory-limit SIZE  refuse a render whose buffers would need more (8G, 512M;
                         default half the physical memory)
  -h, --help             this help
      --version          print the version

exit codes: 0 all frames written, 1 a frame failed at run time, 2 bad command line or input,
3 no usable OpenGL backend.
)";

// The frame named by environment variable VAR plus OFFSET, as a frame spec.
std::string frameFromEnvironment(const ArgCursor& c, const std::string& var, long offset) {
    const char* value = std::getenv(var.c_str());
    if (!value) c.fail("--frame-from-env: environment variable " + var + " is not set");
    std::string text(value);
    long frame = 0;
    auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), frame);
    if (text.empty() || ec != std::errc() || ptr != text.data() + text.size())
        c.fail("--frame-from-env: " + var + "='" + text + "' is not a whole number");
    if (frame + offset < 0)
        c.fail("--frame-from-env: " + var + "=" + text +
               (offset ? " with --frame-offset " + std::to_string(offset) : "") + " gives frame " +
               std::to_string(frame + offset) + " (frames are 0 or more)");
    return std::to_string(frame + offset);
}

// A non-empty pattern for FLAG.
std::string pattern(const ArgCursor& c, const char* flag, const std::string& v) {
    if (v.empty()) c.fail(std::string(flag) + ": empty pattern");
    return v;
}

// Consumes one render option at the cursor into REQ; false if the argument is not one.
bool parseRenderOption(ArgCursor& c, app::RenderRequest& req) {
    std::optional<std::string> v;
    if ((v = c.option("-t", "--technique"))) {
        req.technique = *v;
    } else if ((v = c.option("-D", "--set"))) {
        size_t eq = v->find('=');
        if (eq == std::string::npos || eq == 0)
            c.fail("-D: expected KEY=VALUE, got '" + quoteText(*v) + "'");
        req.overrides.push_back({v->substr(0, eq), v->substr(eq + 1)});
    } else if ((v = c.option("-o", "--output"))) {
        req.output = pattern(c, "--output", *v);
    } else if ((v = c.option("", "--timings"))) {
        req.timings = pattern(c, "--timings", *v);
    } else if ((v = c.option("", "--preview"))) {
        req.preview = pattern(c, "--preview", *v);
    } else if ((v = c.option("", "--exr-compression"))) {
        const auto compression = output::parseExrCompression(*v);
        if (!compression)
            c.fail("--exr-compression: '" + quoteText(*v) + "' is not " +
                   output::kExrCompressionChoices);
        req.exr_compression = *compression;
    } else if ((v = c.option("-f", "--frames"))) {
        req.frames = *v;
    } else if (c.flag("", "--list-frames")) {
        req.list_frames = true;
    } else if (parseRunFlag(c, req.overrides, req.runs)) {
    } else if (parseGltfSceneFlag(c, req.gltf)) {
    } else if (c.flag("", "--skip-existing")) {
        req.skip_existing = true;
    } else if (c.flag("", "--strict")) {
        req.strict = true;
    } else if (c.flag("-q", "--quiet")) {
        req.quiet = true;
    } else {
        return false;
    }
    return true;
}

}  // namespace

int runRender(const Args& args) {
    ArgCursor c("render", args);
    app::RenderRequest req;
    std::optional<std::string> scene, frame_env;
    std::optional<int> frame_offset;
    while (!c.done()) {
        if (c.flag("-h", "--help")) {
            std::fputs(kHelp, stdout);
            return 0;
        }
        if (parseRenderOption(c, req) || parseBackendFlag(c, req.gl) || parseMemoryLimitFlag(c))
            continue;
        if (auto v = c.option("", "--frame-from-env")) {
            if (v->empty()) c.fail("--frame-from-env: empty variable name");
            frame_env = *v;
            continue;
        }
        if (auto v = c.option("", "--frame-offset")) {
            frame_offset = parseInt(c, "--frame-offset", *v, -10'000'000, 10'000'000);
            continue;
        }
        if (auto p = c.positional()) {
            if (scene) c.fail("unexpected argument '" + *p + "': one scene per render");
            scene = *p;
            continue;
        }
        c.unknown();
    }
    if (!scene) c.fail("missing SCENE.json (see --help)");
    if (gltfSceneFlagsGiven(req.gltf) && !scene::isGltfPath(*scene))
        c.fail(std::string(req.gltf.light_size ? "--light-size" : "--no-floor") +
               ": only for a .gltf/.glb model (a scene file has its own lights and objects)");
    if (frame_offset && !frame_env) c.fail("--frame-offset: only with --frame-from-env");
    if (frame_env) {
        if (req.frames) c.fail("--frame-from-env: not with --frames");
        req.frames = frameFromEnvironment(c, *frame_env, frame_offset.value_or(0));
        req.frames_flag = "--frame-from-env";
        req.farm_task = true;
    }
    req.scene = *scene;
    return app::runRenderJob(req);
}

}  // namespace penumbra::cli
