// The render job: see render_job.h.
#include "renderer/render/render_job.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <map>
#include <set>

#include "penumbra/version.h"
#include "renderer/core/atomic_file.h"
#include "renderer/core/error.h"
#include "renderer/core/frame_spec.h"
#include "renderer/core/json_bounds.h"
#include "renderer/core/output_paths.h"
#include "renderer/gl/debug.h"
#include "renderer/output/exr.h"
#include "renderer/output/preview.h"
#include "renderer/output/timing.h"
#include "renderer/render/frame_renderer.h"
#include "renderer/render/memory_budget.h"
#include "renderer/techniques/technique.h"

namespace penumbra::render {
namespace {

using Clock = std::chrono::steady_clock;

struct FramePlan {
    int frame = 0;
    std::string exr, timing, preview;
    bool skip = false;
};

const techniques::TechniqueInfo& findTechniqueOrThrow(const scene::Scene& s,
                                                      const RenderRequest& req) {
    std::string name = s.technique.value("name", std::string("hard"));
    if (const auto* info = techniques::findTechnique(name)) return *info;
    std::string known;
    for (const auto& t : techniques::allTechniques())
        known += (known.empty() ? "" : ", ") + std::string(t.name);
    std::string where = req.technique ? "--technique" : s.path.string() + ": technique.name";
    throw InputError(where + ": unknown technique '" + quoteText(name) + "' (known: " + known +
                     ")");
}

Params resolveFor(const techniques::TechniqueInfo& info, const scene::Scene& s) {
    return resolveParams(info.params, s.technique, s.path.string() + ": technique");
}

std::vector<FramePlan> planFrames(const RenderRequest& req, const std::string& scene_name,
                                  const std::vector<int>& frames) {
    const bool several = frames.size() > 1;
    const std::string exr_pattern = req.output.value_or("out/" + scene_name + ".####.exr");
    std::vector<FramePlan> plans;
    std::map<std::string, int> seen;
    for (int f : frames) {
        FramePlan p;
        p.frame = f;
        p.exr = expandFramePattern(exr_pattern, f, several);
        p.timing = req.timings ? expandFramePattern(*req.timings, f, several)
                               : replaceExtension(p.exr, ".json");
        if (req.preview) p.preview = expandFramePattern(*req.preview, f, several);
        for (const auto& [path, flag] :
             {std::pair{p.exr, "--output"}, std::pair{p.timing, "--timings"},
              std::pair{p.preview, "--preview"}}) {
            if (path.empty()) continue;
            checkOutputPath(path, flag);  // no device, FIFO or folder replaced by the rename
            auto [it, inserted] = seen.emplace(outputIdentity(path), f);
            if (!inserted && it->second == f)
                throw InputError(std::string(flag) + ": '" + quoteText(path) +
                                 "' is another output of frame " + std::to_string(f));
            if (!inserted)
                throw InputError(std::string(flag) + ": frames " + std::to_string(it->second) +
                                 " and " + std::to_string(f) + " would both write '" +
                                 quoteText(path) + "' (use # in the pattern)");
        }
        p.skip = req.skip_existing && std::filesystem::exists(p.exr);
        plans.push_back(p);
    }
    return plans;
}

void checkGlLimits(const scene::Scene& s, const Params& params, const gl::ContextInfo& info) {
    const std::string where = s.path.string() + ": ";
    const int max = std::min(info.max_texture_size, info.max_renderbuffer_size);
    if (s.image.width > max)
        throw InputError(where + "image.width: " + std::to_string(s.image.width) +
                         " exceeds this GL's limit of " + std::to_string(max));
    if (s.image.height > max)
        throw InputError(where + "image.height: " + std::to_string(s.image.height) +
                         " exceeds this GL's limit of " + std::to_string(max));
    if (params.json().contains("map_size") && params.getInt("map_size") > info.max_texture_size)
        throw InputError(
            where + "technique.map_size: " + std::to_string(params.getInt("map_size")) +
            " exceeds this GL's texture limit of " + std::to_string(info.max_texture_size));
    if (s.lights.size() > static_cast<size_t>(info.max_array_layers))
        throw InputError(where + "lights: more lights than this GL's array layers allow");
}

// "frame i of n (frame f), pass, elapsed, ETA" on one rewritten stderr line (a terminal only).
class Progress {
public:
    Progress(bool enabled, size_t total) : enabled_(enabled), total_(total), start_(Clock::now()) {}
    void frame(size_t index, int frame) {
        index_ = index;
        frame_ = frame;
        show("", true);
    }
    void pass(const std::string& name) { show(name, false); }
    void done() {
        if (enabled_ && shown_) std::fprintf(stderr, "\n");
        shown_ = false;
    }

private:
    void show(const std::string& pass, bool force) {
        if (!enabled_) return;
        auto now = Clock::now();
        if (!force && now - last_ < std::chrono::milliseconds(100)) return;
        last_ = now;
        double elapsed = std::chrono::duration<double>(now - start_).count();
        double eta = index_ > 0 ? elapsed / static_cast<double>(index_) *
                                      static_cast<double>(total_ - index_)
                                : 0.0;
        std::fprintf(stderr, "\r\033[Kpenumbra: frame %zu of %zu (frame %d) %-18s elapsed %.1fs",
                     index_ + 1, total_, frame_, pass.c_str(), elapsed);
        if (index_ > 0) std::fprintf(stderr, ", ETA %.1fs", eta);
        std::fflush(stderr);
        shown_ = true;
    }
    bool enabled_;
    bool shown_ = false;
    size_t total_, index_ = 0;
    int frame_ = 0;
    Clock::time_point start_, last_;
};

}  // namespace

int runRenderJob(const RenderRequest& req) {
    const auto job_start = Clock::now();
    // 1. Everything from the input, validated before any GL or output.
    scene::LoadOptions options;
    options.technique = req.technique;
    auto source = scene::SceneSource::load(req.scene, req.overrides, options);
    std::vector<int> frames;
    if (req.frames)
        frames = parseFrameSpec(*req.frames, "--frames");
    else if (source.animationFrames())
        frames =
            parseFrameSpec(*source.animationFrames(), req.scene.string() + ": animation.frames");
    else
        frames = {0};
    scene::Scene first = source.at(frames.front());
    const techniques::TechniqueInfo& info = findTechniqueOrThrow(first, req);
    Params params = resolveFor(info, first);
    for (int f : frames) resolveFor(info, source.at(f));  // animated parameters stay valid
    std::vector<FramePlan> plans = planFrames(req, first.name, frames);
    if (req.list_frames) {
        for (const auto& p : plans)
            if (!p.skip) std::printf("%d\n", p.frame);
        return 0;
    }
    if (std::all_of(plans.begin(), plans.end(), [](const FramePlan& p) { return p.skip; })) {
        if (!req.quiet)
            std::fprintf(stderr, "penumbra: all %zu frames exist already (--skip-existing)\n",
                         plans.size());
        return 0;  // a resumed farm job with nothing left needs no GL context
    }

    // 2. The context (exit 3 if none), then the limits only GL knows.
    auto context = gl::Context::create(req.gl);
    const gl::ContextInfo& glinfo = context->info();
    gl::enableDebugOutput(req.gl.debug);
    checkGlLimits(first, params, glinfo);
    checkMemoryBudget(first, info.name, params, &glinfo);  // exit 2 before any allocation

    // 3. Per-run GPU resources.
    const int width = first.image.width, height = first.image.height;
    FrameRenderer renderer(glinfo, first, info, params);
    PassTimer timer(glinfo.software);

    const nlohmann::json backend = {{"api", glinfo.api},         {"device", glinfo.device},
                                    {"vendor", glinfo.vendor},   {"renderer", glinfo.renderer},
                                    {"version", glinfo.version}, {"clock", timer.clockName()}};
    const bool progress_on = !req.quiet && isatty(STDERR_FILENO);
    Progress progress(progress_on, plans.size());
    if (progress_on) timer.on_begin = [&](const std::string& pass) { progress.pass(pass); };
    int failed = 0, written = 0, skipped = 0;
    for (size_t fi = 0; fi < plans.size(); ++fi) {
        const FramePlan& plan = plans[fi];
        if (plan.skip) {
            ++skipped;
            continue;
        }
        progress.frame(fi, plan.frame);
        try {
            scene::Scene s = source.at(plan.frame);
            renderer.setParams(resolveFor(info, s));
            output::FrameReport report;
            std::map<std::string, size_t> pass_index;
            nlohmann::json stats;
            for (int run = 0; run < req.warmup + req.repeat; ++run) {
                auto frame_start = Clock::now();
                stats = renderer.render(s, timer);
                glFinish();
                double frame_ms =
                    std::chrono::duration<double, std::milli>(Clock::now() - frame_start).count();
                auto times = timer.finishFrame();
                if (run < req.warmup) continue;
                report.frame_ms.push_back(frame_ms);
                for (const auto& t : times) {
                    auto [it, inserted] = pass_index.emplace(t.name, report.passes.size());
                    if (inserted) report.passes.push_back({t.name, timer.clockName(), {}});
                    report.passes[it->second].ms.push_back(t.ms);
                }
            }
            auto read_start = Clock::now();
            output::Image image = renderer.readImage();
            report.passes.push_back(
                {"readback",
                 "cpu",
                 {std::chrono::duration<double, std::milli>(Clock::now() - read_start).count()}});
            image.attributes = {{"penumbra/version", PENUMBRA_VERSION},
                                {"penumbra/commit", PENUMBRA_COMMIT},
                                {"penumbra/technique", std::string(info.name)},
                                {"penumbra/params", renderer.params().json().dump()},
                                {"penumbra/scene", req.scene.string()},
                                {"penumbra/frame", std::to_string(plan.frame)},
                                {"penumbra/samples", std::to_string(renderer.samples())},
                                {"penumbra/backend", glinfo.api},
                                {"penumbra/gl_vendor", glinfo.vendor},
                                {"penumbra/gl_renderer", glinfo.renderer},
                                {"penumbra/gl_version", glinfo.version}};
            output::writeExr(plan.exr, image);
            if (!plan.preview.empty()) output::writePngPreview(plan.preview, image);
            report.scene = req.scene.string();
            report.frame = plan.frame;
            report.technique = std::string(info.name);
            report.params = renderer.params().json();
            report.backend = backend;
            report.width = width;
            report.height = height;
            report.samples = renderer.samples();
            report.warmup = req.warmup;
            report.stats = stats;
            report.stats["triangles"] = renderer.gpuScene().triangleCount();
            report.stats["lights"] = renderer.lightCount();
            report.output = {{"exr", plan.exr}};
            if (!plan.preview.empty()) report.output["preview"] = plan.preview;
            output::writeTimingJson(plan.timing, report);
            ++written;
        } catch (const RuntimeError& e) {
            progress.done();
            std::fprintf(stderr, "penumbra: frame %d: %s\n", plan.frame, e.what());
            ++failed;
        }
    }
    progress.done();
    if (!req.quiet && plans.size() > 1)
        std::fprintf(stderr, "penumbra: %zu frames: %d written, %d skipped, %d failed, %.1f s\n",
                     plans.size(), written, skipped, failed,
                     std::chrono::duration<double>(Clock::now() - job_start).count());
    return failed ? static_cast<int>(ExitCode::RuntimeFailure) : 0;
}

}  // namespace penumbra::render
