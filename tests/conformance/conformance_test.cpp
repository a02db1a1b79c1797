// The conformance label: every technique at its defaults on 13 scenes of the conformance corpus
// (scenes/conformance) at 128 x 96, against `exact` (N = 16), in process. Each run's worst
// shadow-region MAE over the receiving objects must stay within its bound; the full corpus at
// 320 x 240, with contact sheets, is scripts/conformance.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "../gl/gl_test_env.h"
#include "renderer/scene/json_file.h"

using penumbra::output::Image;
using penumbra::testing::channel;

namespace {

const std::vector<std::string> kScenes = {"box_resting",
                                          "spheres_three_sizes",
                                          "duck_resting",
                                          "light_size_0.25",
                                          "light_aspect_1to16",
                                          "light_tilt_45",
                                          "bar_grid",
                                          "under_table",
                                          "two_lights",
                                          "split_roles",
                                          "stacked_boxes",
                                          "tilted_receiver",
                                          "fence"};

struct Run {
    std::string label, technique;
    double bound;     // worst receiver shadow-region MAE allowed over the 13 scenes
    const char* why;  // where the bound comes from
};

// Bounds: the conformance issue's targets (at 320 x 240) where a run meets them here; where it
// does not, the measured worst of this version with a margin of 15 %, so that the label catches
// regressions while the fixes that issue asks for are pending. Measured worst in the comment.
const std::vector<Run> kRuns = {
    {"reference", R"({"name": "reference"})", 0.015,
     "measured 0.0104 (bar_grid; light_size_0.25 was 0.0181 before the horizon rule took the "
     "triangle's plane); the target 0.015 itself"},
    {"adaptive", R"({"name": "adaptive"})", 0.02,
     "measured 0.0116 on the corpus (caster_outside_view), bar_grid 0.0081 since depth 4 (0.0228 "
     "at the 9 x 9 grid of depth 3); the target 0.02 itself"},
    {"ssm", R"({"name": "ssm"})", 0.04,
     "measured 0.0336 (stacked_boxes) with the light-sample masks, which count overlapping "
     "back-projections once; 0.0614 (duck_resting) with the paper's sum of areas (Atty et al. "
     "5.1.2), 0.0904 one-sided; the target is 0.07 on receivers, so 0.04 is that measurement "
     "with a margin of 15 %, to catch a regression to the sum"},
    {"bitmask", R"({"name": "bitmask"})", 0.055,
     "measured 0.0499 (duck_resting: coarse micro-occluders at budget 12) with the far layer, "
     "0.0614 with the map's layer alone (the duck's lower body, which the light's centre does "
     "not see); the target 0.05 is met without a margin, so 0.055 is the measurement with one "
     "of 10 %, which a return to one layer fails"},
    {"css", R"({"name": "css"})", 0.065,
     "measured 0.0571 (duck_resting: the head's shadow on the body, which one depth map and "
     "one blocker depth per kernel cannot hold); the target 0.06 is met without a margin, so "
     "0.065 is the measurement with one of 14 %, which fence fails (0.0693) with a depth range "
     "that reaches the farthest receiver instead of a gap past the casters"},
};

std::string scenePath(const std::string& name) {
    return "../../../scenes/conformance/" + name + ".json";
}

// Indices of SCENE's objects that receive shadows (role both, the default, or receiver).
std::vector<int> receivers(const std::string& name) {
    const auto doc = penumbra::scene::parseJsonText(
        penumbra::scene::readTextFile(
            std::string(PENUMBRA_SOURCE_DIR) + "/scenes/conformance/" + name + ".json", name,
            std::size_t(1) << 20),
        name);
    std::vector<int> ids;
    for (size_t i = 0; i < doc["objects"].size(); ++i) {
        const std::string role = doc["objects"][i].value("shadow", "both");
        if (role == "both" || role == "receiver") ids.push_back(int(i));
    }
    return ids;
}

// Shadow-region MAE (either below 0.999) of IMG's visibility against EXACT's over IDS.
double receiverMae(const Image& exact, const Image& img, const std::vector<int>& ids) {
    const auto& ve = channel(exact, "visibility");
    const auto& v = channel(img, "visibility");
    const auto& id = channel(exact, "id");
    double sum = 0;
    long n = 0;
    for (size_t i = 0; i < v.size(); ++i) {
        if (std::find(ids.begin(), ids.end(), int(id[i])) == ids.end()) continue;
        if (ve[i] >= 0.999f && v[i] >= 0.999f) continue;
        sum += std::fabs(v[i] - ve[i]);
        ++n;
    }
    return n > 0 ? sum / n : 0.0;
}

Image render(const std::string& scene, const std::string& technique) {
    return penumbra::testing::renderScene(
        scenePath(scene),
        {{"image.width", "128"}, {"image.height", "96"}, {"technique", technique}});
}

}  // namespace

TEST(Conformance, EveryTechniqueWithinItsBoundOnTheSubset) {
    std::map<std::string, std::pair<double, std::string>> worst;  // label -> (mae, scene)
    for (const auto& scene : kScenes) {
        const Image exact = render(scene, R"({"name": "exact", "samples": 16})");
        const auto ids = receivers(scene);
        std::printf("%-20s", scene.c_str());
        for (const auto& run : kRuns) {
            const double mae = receiverMae(exact, render(scene, run.technique), ids);
            std::printf(" %s %.4f", run.label.c_str(), mae);
            auto& w = worst[run.label];
            if (mae >= w.first) w = {mae, scene};
        }
        std::printf("\n");
    }
    for (const auto& run : kRuns) {
        const auto& [mae, scene] = worst[run.label];
        std::printf("%-10s worst %.4f (%s), bound %.4f: %s\n", run.label.c_str(), mae,
                    scene.c_str(), run.bound, run.why);
        EXPECT_LE(mae, run.bound) << run.label << " on " << scene;
    }
}
