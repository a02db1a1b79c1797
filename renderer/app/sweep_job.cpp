// The sweep job: see sweep_job.h.
#include "renderer/app/sweep_job.h"

#include "renderer/app/memory_budget.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>

#include "penumbra/version.h"
#include "renderer/core/atomic_file.h"
#include "renderer/core/content_hash.h"
#include "renderer/core/error.h"
#include "renderer/core/json_bounds.h"
#include "renderer/frame/frame_renderer.h"
#include "renderer/gl/debug.h"
#include "renderer/output/compare.h"
#include "renderer/output/exr.h"
#include "renderer/output/heatmap.h"
#include "renderer/output/preview.h"
#include "renderer/output/timing.h"
#include "renderer/scene/json_file.h"
#include "renderer/techniques/technique.h"

namespace penumbra::app {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

constexpr size_t kMaxRuns = 2000;
constexpr size_t kMaxRecordBytes = size_t{16} << 20;  // runs/run-NNNN.json, read back on reruns
constexpr float kHeatmapFullScale = 0.25f;            // |dV| of 0.25 or more is drawn white

// One render to make: its scene settings, validated, and the hash of what determines its image.
struct Job {
    std::vector<scene::Override> overrides;
    std::optional<std::string> technique;
    std::string hash;
    std::string technique_name;
    int width = 0, height = 0;
};

// Loads and validates JOB's scene (exit 2 on bad input) and fills its hash and technique.
void validate(Job& job, const SweepRequest& req) {
    scene::LoadOptions options;
    options.technique = job.technique;
    auto source = scene::SceneSource::load(req.scene, job.overrides, options);
    scene::Scene s = source.at(req.frame);
    job.technique_name = s.technique.value("name", std::string("hard"));
    job.width = s.image.width;
    job.height = s.image.height;
    const auto* info = techniques::findTechnique(job.technique_name);
    if (!info)
        throw InputError(req.scene.string() + ": technique.name: unknown technique '" +
                         quoteText(job.technique_name) + "'");
    checkMemoryBudget(s, job.technique_name,
                      resolveParams(info->params, s.technique, req.scene.string() + ": technique"),
                      nullptr);
    job.hash = contentHash(source.document().dump() + "|frame " + std::to_string(req.frame) + "|" +
                           PENUMBRA_VERSION);
}

struct Rendered {
    output::Image image;
    json passes = json::object();  // grouped medians: "shadow_maps[3]@1" -> "shadow_maps"
    double total_ms = 0;
    json stats;
};

Rendered renderJob(const Job& job, const SweepRequest& req, const gl::ContextInfo& gl, int warmup,
                   int repeat) {
    scene::LoadOptions options;
    options.technique = job.technique;
    auto source = scene::SceneSource::load(req.scene, job.overrides, options);
    scene::Scene s = source.at(req.frame);
    const auto& info = *techniques::findTechnique(job.technique_name);
    frame::FrameRenderer renderer(gl, s, info,
                                  resolveParams(info.params, s.technique, "technique"));
    gl::PassTimer timer(gl.software);
    std::map<std::string, std::vector<double>> grouped;
    std::vector<double> totals;
    Rendered out;
    static const std::regex suffix(R"((\[\d+\])?(@\d+)?$)");
    for (int run = 0; run < warmup + repeat; ++run) {
        out.stats = renderer.render(s, timer);
        auto times = timer.finishFrame();
        if (run < warmup) continue;
        std::map<std::string, double> sums;
        double total = 0;
        for (const auto& t : times) {
            sums[std::regex_replace(t.name, suffix, "")] += t.ms;
            total += t.ms;
        }
        for (const auto& [k, v] : sums) grouped[k].push_back(v);
        totals.push_back(total);
    }
    for (const auto& [k, v] : grouped) out.passes[k] = output::summarize(v).median;
    out.total_ms = output::summarize(totals).median;
    out.image = renderer.readImage();
    out.image.attributes = {{"penumbra/version", PENUMBRA_VERSION},
                            {"penumbra/technique", job.technique_name},
                            {"penumbra/scene", req.scene.string()}};
    return out;
}

json metricsJson(const output::CompareResult& r) {
    json m = {{"mae", r.mae},
              {"rmse", r.rmse},
              {"max", r.max},
              {"p99", r.p99},
              {"fail_fraction", r.fail_fraction},
              {"shadow_mae", r.shadow_mae ? json(*r.shadow_mae) : json(nullptr)},
              {"shadow_pixels", r.shadow_pixels ? json(*r.shadow_pixels) : json(0)}};
    return m;
}

std::string csvCell(const json& v) {
    std::string s = v.is_string() ? v.get<std::string>() : v.dump();
    if (s.find_first_of(",\"\n") == std::string::npos) return s;
    std::string q = "\"";
    for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
    return q + "\"";
}

std::string toCsv(const json& sweep) {
    std::vector<std::string> keys;
    for (const auto& a : sweep["varied"]) keys.push_back(a["key"]);
    std::vector<std::string> metrics = {"mae",        "rmse",          "max",          "p99",
                                        "shadow_mae", "shadow_pixels", "fail_fraction"};
    std::vector<std::string> passes, stats;
    for (const auto& r : sweep["runs"]) {
        for (const auto& [k, v] : r["time_ms"]["passes"].items())
            if (std::find(passes.begin(), passes.end(), k) == passes.end()) passes.push_back(k);
        for (const auto& [k, v] : r["stats"].items())
            if (std::find(stats.begin(), stats.end(), k) == stats.end()) stats.push_back(k);
    }
    std::ostringstream out;
    out << "id,technique";
    for (const auto& k : keys) out << "," << csvCell(k);
    out << ",total_ms";
    for (const auto& p : passes) out << "," << csvCell(p + "_ms");
    for (const auto& m : metrics) out << "," << m;
    for (const auto& s : stats) out << "," << csvCell(s);
    out << ",exr\n";
    for (const auto& r : sweep["runs"]) {
        out << csvCell(r["id"]) << "," << csvCell(r["technique"]);
        for (const auto& k : keys) out << "," << csvCell(r["values"][k]);
        out << "," << r["time_ms"]["total"].dump();
        for (const auto& p : passes)
            out << "," << r["time_ms"]["passes"].value(p, json(nullptr)).dump();
        for (const auto& m : metrics) out << "," << r["metrics"].value(m, json(nullptr)).dump();
        for (const auto& s : stats) out << "," << csvCell(r["stats"].value(s, json(nullptr)));
        out << "," << csvCell(r["exr"]) << "\n";
    }
    return out.str();
}

bool spawnAndWait(const std::vector<std::string>& args, bool quiet,
                  const fs::path& stdin_file = {});

bool runReport(const fs::path& dir, bool quiet) {
    const char* env = std::getenv("PENUMBRA_SWEEP_REPORT");
    fs::path script =
        env && *env ? fs::path(env) : fs::path(PENUMBRA_SOURCE_ROOT) / "scripts" / "sweep-report";
    if (!fs::exists(script)) {
        std::fprintf(stderr,
                     "penumbra: sweep: no report: %s not found (set PENUMBRA_SWEEP_REPORT)\n",
                     script.c_str());
        return false;
    }
    return spawnAndWait({script.string(), dir.string()}, quiet);  // no shell: no quoting
}

// Spawns ARGV (argv[0] looked up in PATH) and waits; STDOUT to /dev/null when QUIET, STDIN
// from STDIN_FILE when given.
bool spawnAndWait(const std::vector<std::string>& args, bool quiet, const fs::path& stdin_file) {
    std::vector<char*> argv;
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    if (quiet) posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
    if (!stdin_file.empty())
        posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, stdin_file.c_str(), O_RDONLY, 0);
    pid_t pid = 0;
    int rc = posix_spawnp(&pid, argv[0], &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    if (rc != 0) return false;
    int status = 0;
    if (waitpid(pid, &status, 0) < 0) return false;
    return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

// Renders runs 1..COUNT as `penumbra sweep ... --run-index K` jobs, REQ.jobs at a time, through
// GNU parallel. No user value is in parallel's command line, where its shell and replacement
// strings ({}, {= perl =}) would interpret it: each job's argv goes NUL-separated to parallel's
// stdin, and the command is only {1} {2} ... {N}, each a quoted word of that argv (-q).
// False when parallel is missing or a job failed.
bool runParallel(const SweepRequest& req, size_t count) {
    std::error_code ec;
    const fs::path self = fs::read_symlink("/proc/self/exe", ec);
    if (ec) return false;
    std::vector<std::string> job = {self.string(), "sweep"};
    job.insert(job.end(), req.job_args.begin(), req.job_args.end());
    job.insert(job.end(), {"--quiet", "--run-index"});
    std::string input;
    for (size_t k = 1; k <= count; ++k) {
        for (const auto& word : job) input += word + '\0';
        input += std::to_string(k) + '\0';
    }
    const fs::path list = req.out / "cache" / (".parallel-jobs." + std::to_string(::getpid()));
    writeFileAtomically(list, input);
    const size_t words = job.size() + 1;
    std::vector<std::string> args = {"parallel", "--will-cite", "-j", std::to_string(req.jobs),
                                     "-0",       "-q",          "-N", std::to_string(words)};
    for (size_t w = 1; w <= words; ++w)
        args.push_back(std::string(1, '{').append(std::to_string(w)).append("}"));
    const bool ok = spawnAndWait(args, req.quiet, list);
    fs::remove(list, ec);
    return ok;
}

}  // namespace

int runSweepJob(const SweepRequest& req) {
    // 1. Every run and every reference, validated before anything renders.
    auto points = cartesianProduct(req.axes, kMaxRuns);
    std::vector<Job> runs, references;
    std::map<std::string, size_t> reference_of_hash;
    std::vector<size_t> run_reference;
    for (const auto& point : points) {
        // Technique parameters (varied, or fixed by -D) belong to the technique under test,
        // not to the reference, unless both are the same technique (-D only).
        auto techniqueKey = [](const std::string& key) {
            return key == "technique" || key.rfind("technique.", 0) == 0;
        };
        Job run{req.overrides, req.technique, {}, {}};
        Job ref{{}, req.reference_technique, {}, {}};
        for (const auto& o : req.overrides)
            if (!techniqueKey(o.key) || req.technique == req.reference_technique)
                ref.overrides.push_back(o);
        for (const auto& [key, value] : point) {
            run.overrides.push_back({key, value.dump()});
            if (!techniqueKey(key)) ref.overrides.push_back({key, value.dump()});
        }
        ref.overrides.insert(ref.overrides.end(), req.reference_sets.begin(),
                             req.reference_sets.end());
        validate(run, req);
        validate(ref, req);
        auto [it, inserted] = reference_of_hash.emplace(ref.hash, references.size());
        if (inserted) references.push_back(ref);
        run_reference.push_back(it->second);
        runs.push_back(std::move(run));
    }
    std::error_code ec;
    fs::create_directories(req.out / "cache", ec);
    fs::create_directories(req.out / "runs", ec);
    if (ec) throw RuntimeError(req.out.string() + ": cannot create folder: " + ec.message());

    // 2. References that the cache lacks.
    if (req.run_index && (*req.run_index < 1 || *req.run_index > static_cast<int>(runs.size())))
        throw InputError("--run-index: " + std::to_string(*req.run_index) + " is not a run (1 to " +
                         std::to_string(runs.size()) + ")");
    int rendered_by_jobs = 0;  // runs the parallel jobs rendered (new run records)
    if (req.jobs > 1 && !req.run_index) {
        auto records = [&] {
            int n = 0;
            for (size_t k = 1; k <= runs.size(); ++k) {
                char name[40];
                std::snprintf(name, sizeof name, "run-%04zu.json", k);
                n += fs::exists(req.out / "runs" / name);
            }
            return n;
        };
        const int before = records();
        if (!runParallel(req, runs.size()))
            std::fprintf(stderr,
                         "penumbra: sweep: some parallel runs failed; retrying them here\n");
        rendered_by_jobs = records() - before;
    }
    std::unique_ptr<gl::Context> context;  // created when something has to render
    auto glInfo = [&]() -> const gl::ContextInfo& {
        if (!context) {
            context = gl::Context::create(req.gl);
            gl::enableDebugOutput(req.gl.debug);
        }
        return context->info();
    };
    int rendered_refs = 0, rendered_runs = 0, failed = 0;
    const bool progress = !req.quiet && isatty(STDERR_FILENO);  // progress only on a terminal
    std::vector<fs::path> ref_paths;  // cache/reference-<hash>.exr per reference
    for (size_t i = 0; i < references.size(); ++i) {
        fs::path path = req.out / "cache" / ("reference-" + references[i].hash + ".exr");
        ref_paths.push_back(path);
        const bool needed =
            !req.run_index || run_reference[static_cast<size_t>(*req.run_index - 1)] == i;
        if (!needed || output::isReadableExr(path)) continue;  // a truncated one is redone
        if (progress)
            std::fprintf(stderr, "penumbra: sweep: reference %zu of %zu\n", i + 1,
                         references.size());
        output::writeExr(path, renderJob(references[i], req, glInfo(), 0, 1).image);
        ++rendered_refs;
    }

    // 3. The runs, each reused when its files exist for the same settings.
    json sweep_runs = json::array();
    output::CompareOptions compare;
    compare.channels = {"visibility"};
    compare.fail = 0.05;  // fail_fraction: share of pixels whose visibility is off by > 0.05
    for (size_t i = 0; i < runs.size(); ++i) {
        if (req.run_index && static_cast<int>(i) + 1 != *req.run_index) continue;
        char id[32];
        std::snprintf(id, sizeof id, "run-%04zu", i + 1);
        const fs::path record = req.out / "runs" / (std::string(id) + ".json");
        json values = json::object();
        for (const auto& [key, value] : points[i]) values[key] = value;
        json entry;
        if (fs::exists(record)) {
            try {  // a record that is not this run's (or not a bounded JSON file) is redone
                json old = scene::parseJsonText(
                    scene::readTextFile(record, record.string(), kMaxRecordBytes), record.string());
                if (old.is_object() && old.value("settings_hash", "") == runs[i].hash &&
                    output::isReadableExr(req.out / old.value("exr", std::string("-"))))
                    entry = old;
            } catch (const InputError&) {
            } catch (const json::exception&) {
            }
        }
        if (entry.is_null()) {
            if (progress)
                std::fprintf(stderr, "penumbra: sweep: run %zu of %zu %s\n", i + 1, runs.size(),
                             values.dump().c_str());
            try {
                Rendered r = renderJob(runs[i], req, glInfo(), req.warmup, req.repeat);
                const std::string base = std::string("runs/") + id;
                output::writeExr(req.out / (base + ".exr"), r.image);
                output::writePngPreview(req.out / (base + ".png"), r.image);
                output::Image ref = output::readExr(ref_paths[run_reference[i]]);
                auto result = output::compareImages(ref, r.image, compare);
                output::writeErrorHeatmap(req.out / (base + ".error.png"), ref, r.image,
                                          "visibility", kHeatmapFullScale);
                entry = {{"id", id},
                         {"values", values},
                         {"technique", runs[i].technique_name},
                         {"settings_hash", runs[i].hash},
                         {"exr", base + ".exr"},
                         {"preview", base + ".png"},
                         {"heatmap", base + ".error.png"},
                         {"reference", fs::relative(ref_paths[run_reference[i]], req.out).string()},
                         {"time_ms", {{"total", r.total_ms}, {"passes", r.passes}}},
                         {"metrics", metricsJson(result)},
                         {"stats", r.stats}};
                writeFileAtomically(record, entry.dump(2) + "\n");
                ++rendered_runs;
            } catch (const RuntimeError& e) {
                std::fprintf(stderr, "penumbra: sweep: %s: %s\n", id, e.what());
                ++failed;
                continue;
            }
        }
        sweep_runs.push_back(entry);
    }

    if (req.run_index) return failed ? static_cast<int>(ExitCode::RuntimeFailure) : 0;

    // 4. The tables, then the report.
    json varied = json::array();
    for (const auto& a : req.axes)
        varied.push_back(
            {{"key", a.key}, {"values", a.values}, {"scale", a.log_scale ? "log" : "linear"}});
    json ref_overrides = json::object();
    for (const auto& o : req.reference_sets) ref_overrides[o.key] = o.value;
    const Job& first = runs.front();
    json sweep = {
        {"schema", "penumbra-sweep"},
        {"schema_version", 1},
        {"scene", req.scene.string()},
        {"technique", first.technique_name},
        {"size", {first.width, first.height}},
        {"frame", req.frame},
        {"varied", varied},
        {"reference", {{"technique", req.reference_technique}, {"overrides", ref_overrides}}},
        {"backend", glInfo().toJson()},
        {"runs", sweep_runs}};
    writeFileAtomically(req.out / "sweep.json", sweep.dump(2) + "\n");
    writeFileAtomically(req.out / "sweep.csv", toCsv(sweep));
    if (!req.quiet)
        std::fprintf(stderr,
                     "penumbra: sweep: %zu runs (%d rendered, %zu reused, %d failed), %zu "
                     "references (%d rendered); %s\n",
                     runs.size(), rendered_runs + rendered_by_jobs,
                     sweep_runs.size() - rendered_runs - rendered_by_jobs, failed,
                     references.size(), rendered_refs, (req.out / "sweep.json").c_str());
    if (req.report && !runReport(req.out, req.quiet)) {
        std::fprintf(stderr, "penumbra: sweep: the report failed\n");
        return static_cast<int>(ExitCode::RuntimeFailure);
    }
    return failed ? static_cast<int>(ExitCode::RuntimeFailure) : 0;
}

}  // namespace penumbra::app
