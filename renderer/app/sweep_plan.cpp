// The sweep's runs and references: see sweep_plan.h.
#include "renderer/app/sweep_plan.h"

#include <filesystem>
#include <map>

#include "penumbra/version.h"
#include "renderer/app/memory_budget.h"
#include "renderer/core/content_hash.h"
#include "renderer/core/error.h"
#include "renderer/core/json_bounds.h"
#include "renderer/techniques/technique.h"

namespace penumbra::app {
namespace {

constexpr size_t kMaxRuns = 2000;

// Content hashes of asset files by path, read once per plan (every run and reference reads
// the same assets).
using FileHashes = std::map<std::string, std::string>;

// Loads and validates RENDER's scene (exit 2 on bad input) and fills its hash and technique.
// A render's hash holds the scene document, the frame, the version and the bytes of every asset
// file read (HASHES keeps them). A reference's also holds the scene's folder: references are
// cached across sweeps (--cache), and two scenes of one text in two folders may name different
// asset files.
void validate(SweepRender& render, const SweepRequest& req, bool reference, FileHashes& hashes) {
    scene::LoadOptions options;
    options.technique = render.technique;
    auto source = scene::SceneSource::load(req.scene, render.overrides, options);
    scene::Scene s = source.at(req.frame);
    render.technique_name = s.technique.value("name", std::string("hard"));
    render.width = s.image.width;
    render.height = s.image.height;
    const auto* info = techniques::findTechnique(render.technique_name);
    if (!info)
        throw InputError(req.scene.string() + ": technique.name: unknown technique '" +
                         quoteText(render.technique_name) + "'");
    checkMemoryBudget(s, *info,
                      resolveParams(info->params, s.technique, req.scene.string() + ": technique"),
                      nullptr);
    std::string key =
        source.document().dump() + "|frame " + std::to_string(req.frame) + "|" + PENUMBRA_VERSION;
    // The bytes of every asset it read (the scene file itself is in the document): a glTF or
    // environment edited in place under the same name renders again.
    const std::vector<std::string> inputs = source.inputFiles();
    for (std::size_t i = 1; i < inputs.size(); ++i) {
        auto [at, added] = hashes.try_emplace(inputs[i]);
        if (added) at->second = fileContentHash(inputs[i]);
        key += "|input " + inputs[i] + " " + at->second;
    }
    if (reference) {
        std::error_code ec;
        const auto folder = std::filesystem::weakly_canonical(
            std::filesystem::absolute(req.scene, ec).parent_path(), ec);
        key += "|folder " + folder.string();
    }
    render.hash = contentHash(key);
}

// Technique parameters (varied, or fixed by -D) belong to the technique under test, not to the
// reference, unless both are the same technique (-D only).
bool techniqueKey(const std::string& key) {
    return key == "technique" || key.rfind("technique.", 0) == 0;
}

}  // namespace

SweepPlan planSweep(const SweepRequest& req) {
    SweepPlan plan;
    plan.points = cartesianProduct(req.axes, kMaxRuns);
    std::map<std::string, size_t> reference_of_hash;
    FileHashes hashes;
    for (const auto& point : plan.points) {
        SweepRender run{req.overrides, req.technique, {}, {}};
        SweepRender ref{{}, req.reference_technique, {}, {}};
        for (const auto& o : req.overrides)
            if (!techniqueKey(o.key) || req.technique == req.reference_technique)
                ref.overrides.push_back(o);
        for (const auto& [key, value] : point) {
            // A varied technique name acts as -t: the scene's technique block is kept only for
            // the technique it names (another's parameters would be unknown keys).
            if (key == "technique.name" && value.is_string())
                run.technique = value.get<std::string>();
            else
                run.overrides.push_back({key, value.dump()});
            if (!techniqueKey(key)) ref.overrides.push_back({key, value.dump()});
        }
        ref.overrides.insert(ref.overrides.end(), req.reference_sets.begin(),
                             req.reference_sets.end());
        validate(run, req, false, hashes);
        validate(ref, req, true, hashes);
        auto [it, inserted] = reference_of_hash.emplace(ref.hash, plan.references.size());
        if (inserted) plan.references.push_back(ref);
        plan.run_reference.push_back(it->second);
        plan.runs.push_back(std::move(run));
    }
    return plan;
}

}  // namespace penumbra::app
