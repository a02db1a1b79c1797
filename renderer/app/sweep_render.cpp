// One render of a sweep, timed --repeat times: its passes grouped by name and their medians
// (see sweep_state.h).
#include <map>
#include <regex>

#include "renderer/app/sweep_state.h"
#include "renderer/frame/render_frame.h"
#include "renderer/output/timing.h"
#include "renderer/techniques/technique.h"

namespace penumbra::app {

using nlohmann::json;

// Renders JOB RUNS times; its passes grouped by name without [batch] and @light, medians of the
// timed runs.
Rendered renderTimed(const SweepRender& job, Sweep& sweep, frame::FrameRuns runs) {
    const SweepRequest& req = sweep.req;
    scene::LoadOptions options;
    options.technique = job.technique;
    auto source = scene::SceneSource::load(req.scene, job.overrides, options);
    scene::Scene s = source.at(req.frame);
    const auto& info = *techniques::findTechnique(job.technique_name);
    frame::RenderedFrame frame = frame::renderFrame(
        sweep.gl(), s, info, resolveParams(info.params, s.technique, "technique"), runs);
    std::map<std::string, std::vector<double>> grouped;
    std::vector<double> totals;
    static const std::regex suffix(R"((\[\d+\])?(@\d+)?$)");
    for (const frame::TimedRun& run : frame.runs) {
        std::map<std::string, double> sums;
        double total = 0;
        for (const auto& t : run.passes) {
            sums[std::regex_replace(t.name, suffix, "")] += t.ms;
            total += t.ms;
        }
        for (const auto& [k, v] : sums) grouped[k].push_back(v);
        totals.push_back(total);
    }
    Rendered out;
    for (const auto& [k, v] : grouped) out.passes[k] = output::summarize(v).median;
    const output::Summary total = output::summarize(totals);
    out.total_ms = total.median;
    out.total_min_ms = total.min;
    out.total_max_ms = total.max;
    out.stats = std::move(frame.stats);
    out.image = std::move(frame.image);
    out.image.attributes.emplace_back("penumbra/scene", req.scene.string());
    return out;
}

}  // namespace penumbra::app
