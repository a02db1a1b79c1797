// The render job: see render_job.h.
#include "renderer/app/render_job.h"

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdio>
#include <map>

#include "penumbra/version.h"
#include "renderer/app/memory_budget.h"
#include "renderer/app/render_job_outputs.h"
#include "renderer/app/render_job_plan.h"
#include "renderer/app/render_job_progress.h"
#include "renderer/core/did_you_mean.h"
#include "renderer/core/error.h"
#include "renderer/core/json_bounds.h"
#include "renderer/frame/camera_attributes.h"
#include "renderer/frame/frame_renderer.h"
#include "renderer/gl/debug.h"
#include "renderer/output/cryptomatte.h"
#include "renderer/output/timing.h"
#include "renderer/scene/overrides.h"
#include "renderer/techniques/technique.h"

namespace penumbra::app {
namespace {

using Clock = std::chrono::steady_clock;

const techniques::TechniqueInfo& findTechniqueOrThrow(const scene::Scene& s,
                                                      const RenderRequest& req) {
    std::string name = s.technique.value("name", std::string("hard"));
    if (const auto* info = techniques::findTechnique(name)) return *info;
    std::string where = req.technique ? "--technique" : s.path.string() + ": technique.name";
    throw InputError(where + ": " + unknownTechniqueMessage(quoteText(name)));
}

Params resolveFor(const techniques::TechniqueInfo& info, const scene::Scene& s) {
    return resolveParams(info.params, s.technique, s.path.string() + ": technique");
}

// Each -D technique.KEY=VALUE checked alone first, so that its error names the flag.
void checkTechniqueOverrides(const techniques::TechniqueInfo& info, const RenderRequest& req) {
    constexpr std::string_view kPrefix = "technique.";
    for (const scene::Override& o : req.overrides) {
        if (o.key.rfind(kPrefix, 0) != 0 || o.key == "technique.name") continue;
        nlohmann::json block = {{"name", std::string(info.name)},
                                {o.key.substr(kPrefix.size()), scene::parseOverrideValue(o)}};
        (void)resolveParams(info.params, block, "-D technique");
    }
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

// A glTF model given where a scene belongs gets a hint instead of a JSON parse error.
void refuseModelAsScene(const std::filesystem::path& file) {
    std::string ext = file.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return std::tolower(c); });
    if (ext == ".gltf" || ext == ".glb")
        throw InputError(file.string() +
                         ": a glTF model, not a scene: name it in a scene's objects "
                         "({\"gltf\": \"" +
                         file.filename().string() + "\"}, see docs/scene-format.md)");
}

}  // namespace

std::string unknownTechniqueMessage(const std::string& name) {
    std::vector<std::string> names;
    std::string known;
    for (const auto& t : techniques::allTechniques()) {
        names.emplace_back(t.name);
        known += (known.empty() ? "" : ", ") + names.back();
    }
    const std::string near = nearestName(name, names);
    return "unknown technique '" + name + "' (" +
           (near.empty() ? "" : "did you mean '" + near + "'? ") + "known: " + known + ")";
}

int runRenderJob(const RenderRequest& req) {
    const auto job_start = Clock::now();
    // 1. Everything from the input, validated before any GL or output.
    refuseModelAsScene(req.scene);
    scene::LoadOptions options;
    options.technique = req.technique;
    auto source = scene::SceneSource::load(req.scene, req.overrides, options);
    const std::vector<int> frames = chooseFrames(req, source);
    scene::Scene first = source.at(frames.front());
    const techniques::TechniqueInfo& info = findTechniqueOrThrow(first, req);
    checkTechniqueOverrides(info, req);
    Params params = resolveFor(info, first);
    for (int f : frames) resolveFor(info, source.at(f));  // animated parameters stay valid
    std::vector<FramePlan> plans = planFrames(req, first.name, frames);
    if (req.list_frames) {
        for (const auto& p : plans)
            if (!p.skip) std::printf("%d\n", p.frame);
        return 0;
    }
    checkOutputFolders(plans);  // an unwritable folder is found before the first frame
    removeStaleTemporaries(plans);
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
    frame::FrameRenderer renderer(glinfo, first, info, params);
    gl::PassTimer timer(glinfo.software);

    const nlohmann::json backend = {{"api", glinfo.api},         {"device", glinfo.device},
                                    {"vendor", glinfo.vendor},   {"renderer", glinfo.renderer},
                                    {"version", glinfo.version}, {"clock", timer.clockName()}};
    const std::string scene_name = canonicalScenePath(req.scene);  // the same from any folder
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
                                {"penumbra/scene", scene_name},
                                {"penumbra/backend", glinfo.api},
                                {"penumbra/gl_vendor", glinfo.vendor},
                                {"penumbra/gl_renderer", glinfo.renderer},
                                {"penumbra/gl_version", glinfo.version}};
            // Numbers as EXR int attributes (they were strings until this change; README
            // changelog).
            image.int_attributes = {{"penumbra/frame", plan.frame},
                                    {"penumbra/samples", renderer.samples()}};
            frame::addCameraAttributes(image, s.camera, image.width, image.height);
            std::vector<std::string> names;
            for (const auto& object : s.objects) names.push_back(object.name);
            output::addCryptomatte(image, "CryptoObject", names, renderer.samples());
            report.scene = scene_name;
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
            writeFrameFiles(plan, image, report);
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

}  // namespace penumbra::app
