// The render job: see render_job.h. Its steps: the input (render_job_checks.h,
// render_job_plan.h), the context and its limits, then each frame through frame::renderFrame
// into its files (render_job_outputs.h), with progress (render_job_progress.h).
#include "renderer/app/render_job.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <map>
#include <memory>
#include <optional>
#include <thread>
#include <utility>

#include "renderer/app/memory_budget.h"
#include "renderer/app/render_job_checks.h"
#include "renderer/app/render_job_outputs.h"
#include "renderer/app/render_job_plan.h"
#include "renderer/app/render_job_progress.h"
#include "renderer/app/render_job_writer.h"
#include "renderer/core/atomic_file.h"
#include "renderer/core/error.h"
#include "renderer/core/process_clock.h"
#include "renderer/frame/camera_attributes.h"
#include "renderer/frame/render_frame.h"
#include "renderer/gl/debug.h"
#include "renderer/gl/program.h"
#include "renderer/gl/program_cache.h"
#include "renderer/output/cryptomatte.h"
#include "renderer/output/timing.h"

namespace penumbra::app {
namespace {

using Clock = std::chrono::steady_clock;

// What step 1 makes of the request: the scene, its technique and the frames to write.
struct JobInput {
    scene::SceneSource source;
    scene::Scene first;  // the first frame's scene
    const techniques::TechniqueInfo& info;
    Params params;  // the first frame's
    std::vector<FramePlan> plans;
};

// 1. Everything from the input, validated before any GL or output.
JobInput loadInput(const RenderRequest& req) {
    scene::LoadOptions options;
    options.technique = req.technique;
    options.gltf = req.gltf;
    auto source = scene::SceneSource::load(req.scene, req.overrides, options);
    const std::vector<int> frames = chooseFrames(req, source);
    scene::Scene first = source.at(frames.front());
    const techniques::TechniqueInfo& info = findTechniqueOrThrow(first, req);
    checkTechniqueOverrides(info, req);
    Params params = resolveFor(info, first);
    for (int f : frames) resolveFor(info, source.at(f));  // animated parameters stay valid
    std::vector<FramePlan> plans = planFrames(req, first.name, frames);
    checkOutputsAreNotInputs(req, plans, source.inputFiles());
    return {std::move(source), std::move(first), info, std::move(params), std::move(plans)};
}

// The frames still to write: false when --skip-existing leaves none. Output folders are checked
// and stale temporaries removed first, so an unwritable folder is found before the first frame.
bool prepareOutputs(const RenderRequest& req, const std::vector<FramePlan>& plans) {
    checkOutputFolders(plans);
    removeStaleTemporaries(plans);
    if (std::any_of(plans.begin(), plans.end(), [](const FramePlan& p) { return !p.skip; }))
        return true;
    if (!req.quiet)
        std::fprintf(stderr, "penumbra: all %zu frames exist already (--skip-existing)\n",
                     plans.size());
    return false;  // a resumed farm job with nothing left needs no GL context
}

// What every frame of the job shares: the renderer, its timer, the backend and the scene name.
struct JobFrames {
    const RenderRequest& req;
    const JobInput& in;
    const gl::ContextInfo& gl;
    frame::FrameRenderer& renderer;
    gl::PassTimer& timer;
    nlohmann::json backend;
    std::string scene_name;          // canonical: the same from any folder
    const double& ms_to_first_pass;  // from the process's start; -1 until the first pass
    output::PixelBuffers& buffers;   // the frames' pixel storage, reused by the writer's work
};

// The timing report of R: passes in first-run order with one figure per timed run.
output::FrameReport timingReport(const frame::RenderedFrame& r, const char* clock) {
    output::FrameReport report;
    std::map<std::string, size_t> pass_index;
    for (const frame::TimedRun& run : r.runs) {
        report.frame_ms.push_back(run.frame_ms);
        for (const auto& t : run.passes) {
            auto [it, inserted] = pass_index.emplace(t.name, report.passes.size());
            if (inserted) report.passes.push_back({t.name, clock, {}});
            report.passes[it->second].ms.push_back(t.ms);
        }
    }
    return report;  // the readback is added when it is done (handOver)
}

// The render job's header attributes after renderFrame's: scene, backend, frame, samples,
// camera, Cryptomatte.
void addJobAttributes(output::Image& image, const JobFrames& job, const scene::Scene& s,
                      int frame) {
    image.attributes.insert(image.attributes.end(), {{"penumbra/scene", job.scene_name},
                                                     {"penumbra/backend", job.gl.api},
                                                     {"penumbra/gl_vendor", job.gl.vendor},
                                                     {"penumbra/gl_renderer", job.gl.renderer},
                                                     {"penumbra/gl_version", job.gl.version}});
    // Numbers as EXR int attributes (they were strings until this change; README changelog).
    image.int_attributes = {{"penumbra/frame", frame},
                            {"penumbra/samples", job.renderer.samples()}};
    frame::addCameraAttributes(image, s.camera, image.width, image.height);
    std::vector<std::string> names;
    for (const auto& object : s.objects) names.push_back(object.name);
    output::addCryptomatte(image, "CryptoObject", names, job.renderer.samples());
}

// A frame rendered with its readback under way, and what its files need.
struct RenderedPlan {
    const FramePlan* plan;
    scene::Scene scene;
    frame::RenderedFrame rendered;
    output::FrameReport report;  // all but the readback's time
};

// The timing report of a frame just rendered (the renderer's parameters are still its own).
output::FrameReport frameReport(const JobFrames& job, const FramePlan& plan,
                                const frame::RenderedFrame& r) {
    output::FrameReport report = timingReport(r, job.timer.clockName());
    report.scene = job.scene_name;
    report.frame = plan.frame;
    report.technique = std::string(job.in.info.name);
    report.params = job.renderer.params().json();
    report.backend = job.backend;
    report.width = job.in.first.image.width;
    report.height = job.in.first.image.height;
    report.samples = job.renderer.samples();
    report.warmup = job.req.runs.warmup;
    const gl::ProgramCacheStats programs = gl::programCacheStats();
    report.process = {{"programs_compiled", programs.compiled},
                      {"programs_from_cache", programs.from_cache}};
    if (job.ms_to_first_pass >= 0) report.process["ms_to_first_pass"] = job.ms_to_first_pass;
    report.stats = r.stats;
    report.stats["triangles"] = job.renderer.gpuScene().triangleCount();
    report.stats["lights"] = job.renderer.lightCount();
    report.output = {{"exr", plan.exr}};
    if (!plan.preview.empty()) report.output["preview"] = plan.preview;
    return report;
}

// Renders PLAN's frame; its readback is left running. Throws RuntimeError.
RenderedPlan renderPlannedFrame(const JobFrames& job, const FramePlan& plan) {
    scene::Scene s = job.in.source.at(plan.frame);
    frame::RenderedFrame r = frame::renderFrameDeferred(job.renderer, s, resolveFor(job.in.info, s),
                                                        job.timer, job.req.runs);
    output::FrameReport report = frameReport(job, plan, r);
    return {&plan, std::move(s), std::move(r), std::move(report)};
}

// Waits for P's readback (GL thread), then hands WRITER the rest: the image assembled, its
// attributes, the EXR, timing JSON and preview written. Throws RuntimeError.
void handOver(const JobFrames& job, FrameWriter& writer, RenderedPlan&& p) {
    const auto wait_start = Clock::now();
    p.rendered.readback.wait();
    p.rendered.readback_ms +=
        std::chrono::duration<double, std::milli>(Clock::now() - wait_start).count();
    p.report.passes.push_back({"readback", "cpu", {p.rendered.readback_ms}});
    auto frame = std::make_shared<RenderedPlan>(std::move(p));
    writer.submit(frame->plan->frame, [&job, frame] {
        frame::finishImage(frame->rendered, &job.buffers);
        addJobAttributes(frame->rendered.image, job, frame->scene, frame->plan->frame);
        writeFrameFiles(*frame->plan, frame->rendered.image, frame->report,
                        job.req.exr_compression);
        job.buffers.recycle(std::move(frame->rendered.image));
    });
}

struct Tally {
    int written = 0, skipped = 0, failed = 0;
};

// One line per failed frame; counts the rest as written.
void countOutcomes(std::vector<WriteOutcome> outcomes, Progress& progress, Tally& tally) {
    for (const WriteOutcome& o : outcomes) {
        if (o.message.empty()) {
            ++tally.written;
            continue;
        }
        progress.done();
        std::fprintf(stderr, "penumbra: frame %d: %s\n", o.frame, o.message.c_str());
        ++tally.failed;
    }
}

// 3. Per-run GPU resources, then every planned frame; a frame that fails is counted, not fatal.
// Frame N's readback completes while frame N + 1 renders, and its files are written on the
// writer's thread while the frames after it render.
Tally renderFrames(const RenderRequest& req, const JobInput& in, const gl::ContextInfo& gl,
                   int writers) {
    frame::FrameRenderer renderer(gl, in.first, in.info, in.params);
    gl::PassTimer timer(gl.software);
    const nlohmann::json backend = {{"api", gl.api},         {"device", gl.device},
                                    {"vendor", gl.vendor},   {"renderer", gl.renderer},
                                    {"version", gl.version}, {"clock", timer.clockName()}};
    double ms_to_first_pass = -1;
    output::PixelBuffers buffers;  // before WRITER: its work uses them
    const JobFrames job{
        req,    in, gl, renderer, timer, backend, canonicalScenePath(req.scene), ms_to_first_pass,
        buffers};
    const bool progress_on = !req.quiet && isatty(STDERR_FILENO);
    Progress progress(progress_on, in.plans.size());
    timer.on_begin = [&](const std::string& pass) {
        if (ms_to_first_pass < 0) ms_to_first_pass = processAgeMs();
        if (progress_on) progress.pass(pass);
    };
    Tally tally;
    FrameWriter writer(writers, FrameWriter::serialRequested());  // before PENDING: outlived by it
    std::optional<RenderedPlan> pending;  // rendered, its readback not yet waited for
    auto handOverPending = [&] {
        if (!pending) return;
        const int frame = pending->plan->frame;
        try {
            handOver(job, writer, *std::exchange(pending, std::nullopt));
        } catch (const RuntimeError& e) {
            countOutcomes({{frame, e.what()}}, progress, tally);
        }
        countOutcomes(writer.takeOutcomes(), progress, tally);
    };
    for (size_t fi = 0; fi < in.plans.size(); ++fi) {
        const FramePlan& plan = in.plans[fi];
        if (plan.skip) {
            ++tally.skipped;
            continue;
        }
        progress.frame(fi, plan.frame);
        try {
            RenderedPlan next = renderPlannedFrame(job, plan);
            handOverPending();
            pending = std::move(next);
        } catch (const RuntimeError& e) {
            handOverPending();
            countOutcomes({{plan.frame, e.what()}}, progress, tally);
        }
    }
    handOverPending();
    writer.finish();
    countOutcomes(writer.takeOutcomes(), progress, tally);
    progress.done();
    return tally;
}

}  // namespace

int runRenderJob(const RenderRequest& req) {
    const auto job_start = Clock::now();
    const JobInput in = loadInput(req);  // 1.
    if (req.list_frames) {
        for (const auto& p : in.plans)
            if (!p.skip) std::printf("%d\n", p.frame);
        return 0;
    }
    const int writers = FrameWriter::workersFor(std::thread::hardware_concurrency());
    removeTemporariesOnSignal();  // Ctrl-C leaves no temporary behind, even mid-write
    if (!prepareOutputs(req, in.plans)) return 0;

    // 2. The context (exit 3 if none), then the limits only GL knows.
    auto context = gl::Context::create(req.gl);
    const gl::ContextInfo& glinfo = context->info();
    gl::enableDebugOutput(req.gl.debug);
    gl::setStrictUniforms(req.gl.debug);  // a uniform no shader declares is a bug: fail
    checkGlLimits(in.first, in.info, in.params, glinfo);
    // A sequence has up to 2 + WRITERS frames in flight: one a writer writes, one read back,
    // one rendering.
    const auto to_render =
        std::count_if(in.plans.begin(), in.plans.end(), [](const FramePlan& p) { return !p.skip; });
    checkMemoryBudget(in.first, in.info, in.params, &glinfo,
                      static_cast<int>(std::min<long>(to_render, 2 + writers)));  // exit 2 first

    const Tally tally = renderFrames(req, in, glinfo, writers);  // 3.
    if (!req.quiet && in.plans.size() > 1)
        std::fprintf(stderr, "penumbra: %zu frames: %d written, %d skipped, %d failed, %.1f s\n",
                     in.plans.size(), tally.written, tally.skipped, tally.failed,
                     std::chrono::duration<double>(Clock::now() - job_start).count());
    return tally.failed ? static_cast<int>(ExitCode::RuntimeFailure) : 0;
}

}  // namespace penumbra::app
