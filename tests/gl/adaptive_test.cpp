// `adaptive` on small scenes: the quadtree's map and comparison counts, the refinement
// diagnostic, and shadow-region error against `exact` N = 32 for fewer maps than N = 16.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "gl_test_env.h"

using penumbra::testing::channel;
using penumbra::testing::shadowRegionMae;

namespace {

struct Result {
    std::vector<float> visibility;
    std::vector<float> depth;  // adaptive.depth, empty for other techniques
    nlohmann::json stats;
};

// Renders tests/data/gl/NAME with TECHNIQUE (a JSON block) and further scene OVERRIDES and
// returns visibility, the refinement diagnostic and the statistics.
Result render(const std::string& name, const std::string& technique,
              std::vector<penumbra::scene::Override> overrides = {}) {
    overrides.push_back({"technique", technique});
    Result r;
    const auto image = penumbra::testing::renderScene(name, overrides, 0, &r.stats);
    r.visibility = channel(image, "visibility");
    if (image.find("adaptive.depth")) r.depth = channel(image, "adaptive.depth");
    return r;
}

std::string adaptive(const std::string& extra = "") {
    return R"({"name": "adaptive", "map_size": 512)" + extra + "}";
}
// The paper's refinement rule (eq. 4 with epsilon) instead of the default error metric.
std::string paper(const std::string& extra = "") {
    return adaptive(R"(, "metric": "global")" + extra);
}
std::string reference(int n) {
    return R"({"name": "reference", "map_size": 512, "samples": )" + std::to_string(n) + "}";
}

// The issue's bar on SCENE: adaptive at most as far from exact N = 32 as reference N = 8 is,
// with at most a third of the 256 maps reference N = 16 renders, within the 9 x 9 grid of depth
// 3. (At its defaults, depth 4, the summed estimate refines these scenes past 85 maps.)
void checkAgainstReference(const std::string& scene) {
    const auto truth = render(scene, penumbra::testing::kGroundTruth).visibility;
    const double ref8 = shadowRegionMae(render(scene, reference(8)).visibility, truth);
    const auto a = render(scene, adaptive(R"(, "max_depth": 3, "target_error": 0.007)"));
    const double mae = shadowRegionMae(a.visibility, truth);
    const int maps = a.stats.value("maps_rendered", 0);
    std::printf(
        "%s: adaptive MAE %.5f with %d maps (depth %d, %d comparisons); reference N=8 "
        "MAE %.5f with 64 maps\n",
        scene.c_str(), mae, maps, a.stats.value("depth_reached", 0),
        a.stats.value("comparisons", 0), ref8);
    EXPECT_LE(mae, ref8);
    EXPECT_LE(maps, 85);  // a third of reference N = 16's 256 maps
}

}  // namespace

TEST(AdaptiveGL, FullRefinementSharesCornerSamples) {
    // epsilon 0 refines every cell: depth 2 is the full 5 x 5 grid, each shared corner
    // rendered once, and 2 comparisons for each of the 1 + 4 cells above the last level.
    auto r = render("closed_form.json", paper(R"(, "epsilon": 0, "max_depth": 2)"));
    EXPECT_EQ(r.stats.value("maps_rendered", 0), 25);
    EXPECT_EQ(r.stats.value("comparisons", 0), 10);
    EXPECT_EQ(r.stats.value("queries", 0), 10);
    EXPECT_EQ(r.stats.value("depth_reached", 0), 2);
}

TEST(AdaptiveGL, MapBudgetStopsRefinement) {
    auto r = render("closed_form.json", paper(R"(, "epsilon": 0, "max_depth": 4, "max_maps": 12)"));
    EXPECT_LE(r.stats.value("maps_rendered", 0), 12);
    EXPECT_TRUE(r.stats.value("map_budget_hit", false));
}

TEST(AdaptiveGL, DepthDiagnosticMarksThePenumbra) {
    // Stride 1: with a stride, a comparison pixel marks its whole block, past the edge.
    auto r = render("closed_form.json", adaptive(R"(, "compare_stride": 1)"));
    ASSERT_EQ(r.depth.size(), r.visibility.size());
    long marked = 0, marked_lit = 0;
    for (size_t i = 0; i < r.depth.size(); ++i) {
        if (r.depth[i] <= 0.0f) continue;
        ++marked;
        marked_lit += r.visibility[i] >= 0.999f;
    }
    EXPECT_GT(marked, 500);
    // Disagreement between maps means some maps shadow the pixel, so it is not fully lit; 2 %
    // allowance because the comparison projects the receiver itself while the shadow test
    // projects it offset along its normal, which moves the outer penumbra edge by a texel.
    EXPECT_LE(double(marked_lit), 0.02 * double(marked));
}

TEST(AdaptiveGL, CompareStrideEstimatesTheFullCount) {
    // Epsilon 0.01 leaves the tree partly refined, so the counts decide. Every 2nd pixel
    // along x and y, counted 4 times, and every 4th (1/16 of the pixels) must refine the same
    // cells as every pixel but one whose count lies at epsilon: its split adds 3 maps, and
    // which way it goes depends on the jitter (seeds 1-6: 22 or 25 maps at stride 1, stride 2
    // the same on 5 of them, stride 4 on 4).
    int maps[3];
    const int strides[3] = {1, 2, 4};
    for (int i = 0; i < 3; ++i)
        maps[i] = render("closed_form.json", paper(R"(, "epsilon": 0.01, "compare_stride": )" +
                                                   std::to_string(strides[i])))
                      .stats.value("maps_rendered", 0);
    std::printf("maps with compare stride 1, 2, 4: %d, %d, %d\n", maps[0], maps[1], maps[2]);
    EXPECT_GT(maps[0], 9);   // partly refined: more than depth 1's 9 maps
    EXPECT_LT(maps[0], 81);  // and less than the full depth-3 grid
    EXPECT_NEAR(maps[1], maps[0], 3);
    EXPECT_NEAR(maps[2], maps[0], 3);
}

TEST(AdaptiveGL, WeightingsOnANonUniformRefinement) {
    // Epsilon 0.01 leaves the closed-form quadtree partly refined (22 maps), where the three
    // weightings differ. Area weights integrate the bilinear interpolant of the samples.
    const auto truth = render("closed_form.json", penumbra::testing::kGroundTruth).visibility;
    double mae[3];
    const char* names[3] = {"area", "paper", "equal"};
    for (int i = 0; i < 3; ++i) {
        auto r = render("closed_form.json",
                        paper(std::string(R"(, "epsilon": 0.01, "weights": ")") + names[i] + "\""));
        mae[i] = shadowRegionMae(r.visibility, truth);
        std::printf("weights %s: MAE %.5f with %d maps\n", names[i], mae[i],
                    r.stats.value("maps_rendered", 0));
    }
    // Measured 0.049 (area), 0.086 (paper), 0.062 (equal): on this partial refinement the
    // paper's depth weights overweight the coarse corners; area weights are clearly best.
    EXPECT_LT(mae[0], mae[1]);
    EXPECT_LT(mae[0], mae[2]);
}

TEST(AdaptiveGL, PcfSoftensTheEvaluation) {
    auto sharp = render("closed_form.json", paper(R"(, "epsilon": 1)"));
    auto soft = render("closed_form.json", paper(R"(, "epsilon": 1, "pcf": 5)"));
    // Four corner maps alone give visibility in steps of 1/4; a 5 x 5 kernel fills between.
    auto partial = [](const std::vector<float>& v) {
        long n = 0;
        for (float x : v) {
            const float steps = x * 4.0f;
            n += std::fabs(steps - std::round(steps)) > 0.01f;
        }
        return n;
    };
    EXPECT_EQ(partial(sharp.visibility), 0);
    EXPECT_GT(partial(soft.visibility), 50);
}

TEST(AdaptiveGL, ClosedFormMatchesReferenceWithFewMaps) {
    checkAgainstReference("closed_form.json");
}

TEST(AdaptiveGL, DefaultSceneMatchesReferenceWithFewMaps) {
    checkAgainstReference("adaptive_default.json");
}

TEST(AdaptiveGL, ErrorFallsAsEpsilonFalls) {
    const auto truth = render("closed_form.json", penumbra::testing::kGroundTruth).visibility;
    double last = 1e9;
    int last_maps = 0;
    for (const char* eps : {"0.05", "0.01", "0.003", "0.0"}) {
        auto r = render("closed_form.json", paper(std::string(R"(, "epsilon": )") + eps));
        const double mae = shadowRegionMae(r.visibility, truth);
        const int maps = r.stats.value("maps_rendered", 0);
        std::printf("epsilon %s: MAE %.5f with %d maps\n", eps, mae, maps);
        EXPECT_LE(mae, last);  // the same jittered lattice, refined further: never worse here
        EXPECT_GE(maps, last_maps);
        last = mae;
        last_maps = maps;
    }
    EXPECT_EQ(last_maps, 289);  // epsilon 0: the full 17 x 17 grid of max_depth 4
}

TEST(AdaptiveGL, AccumulationPathMatchesTextureArrayPath) {
    // Both evaluate sum_k w_k lit_k / sum_k w_k; the accumulation buffer normalises at the end.
    // (Over the whole image, the default: with refine_tile each tile's paper weights are
    // normalised over the samples of its own leaves, which the accumulation can't do.)
    const std::string opts = R"(, "weights": "paper")";
    auto array = render("closed_form.json", adaptive(opts));
    auto accum = render("closed_form.json", adaptive(opts + R"(, "evaluation": "accumulate")"));
    EXPECT_EQ(array.stats.value("maps_rendered", 0), accum.stats.value("maps_rendered", 0));
    const double max = penumbra::testing::maxAbsDifference(array.visibility, accum.visibility);
    // Float sums in a different order and one extra multiply: a few ulps of 1.
    EXPECT_LE(max, 1e-5);
}

TEST(AdaptiveGL, RelativeGammaRefinesLikeAbsolute) {
    // Depths are normalised to [0,1] with casters near the middle, so eq. 7 with gamma 0.02
    // flags roughly the pixels eq. 3 with gamma 0.01 does; both must refine the penumbra.
    auto r = render("closed_form.json", paper(R"(, "gamma_mode": "relative", "gamma": 0.02)"));
    EXPECT_GE(r.stats.value("depth_reached", 0), 2);
    EXPECT_GT(r.stats.value("comparisons", 0), 2);
}

TEST(AdaptiveGL, LinearLightSubdividesIn1D) {
    // A light of (nearly: the scene format rejects 0) zero height: samples at the two ends,
    // one comparison per segment, halving; subdivision "linear" forces the same on any light.
    auto r =
        render("closed_form.json", paper(R"(, "epsilon": 0)"), {{"lights.0.size", "[1, 0.0005]"}});
    EXPECT_EQ(r.stats.value("maps_rendered", 0), 17);  // 2^4 + 1 points at max_depth 4
    EXPECT_EQ(r.stats.value("comparisons", 0), 15);    // 1 + 2 + 4 + 8 segments
    auto forced = render("closed_form.json", paper(R"(, "epsilon": 0, "subdivision": "linear")"));
    EXPECT_EQ(forced.stats.value("maps_rendered", 0), 17);
}

TEST(AdaptiveGL, TileMetricRefinesASmallShadowTheGlobalOneMisses) {
    // The shadow covers about 1 % of the frame: the paper's global metric (5.1) sees too few
    // disagreeing pixels and stops at the corners; the tile metric refines where it is.
    const std::string scene = "adaptive_small_shadow.json";
    const auto truth = render(scene, penumbra::testing::kGroundTruth).visibility;
    auto global = render(scene, paper());
    auto tile = render(scene, adaptive(R"(, "metric": "tile")"));
    const double mae_global = shadowRegionMae(global.visibility, truth, 100);
    const double mae_tile = shadowRegionMae(tile.visibility, truth, 100);
    std::printf(
        "small shadow: global metric MAE %.5f with %d maps, tile metric MAE %.5f with %d "
        "maps\n",
        mae_global, global.stats.value("maps_rendered", 0), mae_tile,
        tile.stats.value("maps_rendered", 0));
    EXPECT_EQ(global.stats.value("maps_rendered", 0), 4);
    EXPECT_GT(tile.stats.value("maps_rendered", 0), 4);
    EXPECT_LT(mae_tile, 0.5 * mae_global);
}

TEST(AdaptiveGL, LightCentreReprojectionIsViewIndependent) {
    // Section 4.1: comparisons in a view from the light's centre do not depend on the camera,
    // so two cameras get the same refinement; the shadow still matches the reference.
    const std::string opts = R"(, "reprojection": "light_centre")";
    auto a = render("closed_form.json", adaptive(opts));
    auto b = render("closed_form.json", adaptive(opts), {{"camera.position", "[1.5, 3.5, 2.0]"}});
    EXPECT_EQ(a.stats.value("maps_rendered", 0), b.stats.value("maps_rendered", 0));
    EXPECT_EQ(a.stats.value("comparisons", 0), b.stats.value("comparisons", 0));
    EXPECT_GT(a.stats.value("maps_rendered", 0), 4);
    const auto truth = render("closed_form.json", penumbra::testing::kGroundTruth).visibility;
    const double mae = shadowRegionMae(a.visibility, truth);
    const double ref4 = shadowRegionMae(render("closed_form.json", reference(4)).visibility, truth);
    std::printf("light-centre reprojection: MAE %.5f with %d maps; reference N=4 MAE %.5f\n", mae,
                a.stats.value("maps_rendered", 0), ref4);
    // No accuracy bar of the paper's for this mode: it refines where the light, not the camera,
    // sees disagreement; require it to beat the 16 maps of reference N = 4.
    EXPECT_LE(mae, ref4);
}

TEST(AdaptiveGL, ShadowTestComparisonRefinesWhereShadowsDiffer) {
    // Comparing hard-test results ignores depth differences that change no shadow (a caster
    // seen at two depths by both maps), so it refines at most where depths do. Measured at
    // epsilon 0.01: equal on the closed form (22 maps); on the default scene 14 maps (MAE 0.045)
    // against 75 (0.011), as depth differences over the casters themselves no longer count.
    for (const char* scene : {"closed_form.json", "adaptive_default.json"}) {
        const auto truth = render(scene, penumbra::testing::kGroundTruth).visibility;
        auto depth = render(scene, paper(R"(, "epsilon": 0.01)"));
        auto tests = render(scene, paper(R"(, "epsilon": 0.01, "compare": "shadow_test")"));
        const double mae_depth = shadowRegionMae(depth.visibility, truth);
        const double mae_tests = shadowRegionMae(tests.visibility, truth);
        std::printf(
            "%s: depth comparison MAE %.5f with %d maps, %d comparisons; shadow-test "
            "comparison MAE %.5f with %d maps, %d comparisons\n",
            scene, mae_depth, depth.stats.value("maps_rendered", 0),
            depth.stats.value("comparisons", 0), mae_tests, tests.stats.value("maps_rendered", 0),
            tests.stats.value("comparisons", 0));
        EXPECT_GT(tests.stats.value("maps_rendered", 0), 4);
        EXPECT_LE(tests.stats.value("maps_rendered", 0), depth.stats.value("maps_rendered", 0));
    }
}

TEST(AdaptiveGL, DefaultStorageHoldsOneBatchOfMaps) {
    // The default storage tests each map right after its batch is rendered and keeps its shadow
    // bits, so 81 maps need no more than one batch of 32 alive; the array holds them all.
    const std::string opts = R"(, "max_depth": 3, "target_error": 0)";
    auto bits = render("closed_form.json", adaptive(opts));
    auto array = render("closed_form.json", adaptive(opts + R"(, "storage": "array")"));
    EXPECT_EQ(bits.stats.value("maps_rendered", 0), 81);
    EXPECT_LE(bits.stats.value("maps_held", 1 << 30), 32);
    EXPECT_GE(array.stats.value("maps_held", 0), 81);
    // The same tests, comparisons and weights: the same refinement and visibility.
    EXPECT_EQ(array.stats.value("maps_rendered", 0), 81);
    EXPECT_LE(penumbra::testing::maxAbsDifference(bits.visibility, array.visibility), 1e-5);
}

TEST(AdaptiveGL, DefaultStorageRefinesAsTheArray) {
    // A partial refinement (target 0.007 stops short of the grid): the bits' comparisons
    // choose the same cells as the shadow-bits pass over the array's maps.
    auto bits = render("closed_form.json", adaptive(R"(, "target_error": 0.007)"));
    auto array =
        render("closed_form.json", adaptive(R"(, "target_error": 0.007, "storage": "array")"));
    EXPECT_EQ(bits.stats.value("maps_rendered", 0), array.stats.value("maps_rendered", 0));
    EXPECT_EQ(bits.stats.value("comparisons", 0), array.stats.value("comparisons", 0));
    EXPECT_DOUBLE_EQ(bits.stats.value("estimated_error", 0.0),
                     array.stats.value("estimated_error", 0.0));
    EXPECT_EQ(bits.depth, array.depth);
    EXPECT_LE(penumbra::testing::maxAbsDifference(bits.visibility, array.visibility), 1e-5);
}

TEST(AdaptiveGL, PixelsNoCasterCanShadowAreNotTestedAndLookTheSame) {
    // skip_lit marks the pixels some caster may shadow from some point of the light (the
    // pyramid from the pixel to the light searched in the casters' min distances from its
    // centre) and tests the maps only there; the rest are lit by every map anyway. On thin
    // bars, a small shadow, a tilted box, a box that casts on itself and the default scene the
    // image is the same as with every pixel tested, and fewer than half the pixels are tested
    // where the shadow is small.
    for (const char* scene : {"adaptive_bars.json", "adaptive_small_shadow.json", "tilted_box.json",
                              "adaptive_default.json", "both_box.json"}) {
        SCOPED_TRACE(scene);
        auto all = render(scene, adaptive(R"(, "skip_lit": false)"));
        auto some = render(scene, adaptive());
        EXPECT_FALSE(all.stats.contains("tested_pixels"));
        const double tested = some.stats.value("tested_pixels", -1.0);
        const auto pixels = double(all.visibility.size());
        std::printf("%s: %.0f of %.0f pixels tested\n", scene, tested, pixels);
        EXPECT_GT(tested, 0.0);
        EXPECT_LT(tested, pixels);
        EXPECT_EQ(some.stats.value("maps_rendered", 0), all.stats.value("maps_rendered", 0));
        EXPECT_LE(penumbra::testing::maxAbsDifference(some.visibility, all.visibility), 1e-6);
    }
    const auto small = render("adaptive_small_shadow.json", adaptive());
    EXPECT_LT(small.stats.value("tested_pixels", 0.0), 0.5 * double(small.visibility.size()));
}

TEST(AdaptiveGL, AStripLightsCastersAreMarkedAsAnySquareLights) {
    // A 1.5 x 0.001 light (a tube: 1D subdivision): the lit region's window had the light's
    // 1500:1 aspect, the casters fell between its texels, no pixel was marked and no shadow
    // drawn (mean visibility 0.99998 against exact's 0.978). Its own window marks them.
    const std::vector<penumbra::scene::Override> strip = {{"lights.0.size", "[1.5, 0.001]"}};
    const auto all = render("adaptive_two_shadows.json", adaptive(R"(, "skip_lit": false)"), strip);
    const auto some = render("adaptive_two_shadows.json", adaptive(), strip);
    const auto truth = render("adaptive_two_shadows.json", penumbra::testing::kGroundTruth, strip);
    const double tested = some.stats.value("tested_pixels", 0.0);
    const double mae = shadowRegionMae(some.visibility, truth.visibility);
    std::printf("strip light: %.0f pixels tested, %d maps, MAE %.5f\n", tested,
                some.stats.value("maps_rendered", 0), mae);
    EXPECT_GT(tested, 1000.0);
    EXPECT_LE(penumbra::testing::maxAbsDifference(some.visibility, all.visibility), 1e-6);
    EXPECT_LE(mae, 0.02);  // adaptive's conformance bound
}

TEST(AdaptiveGL, NarrowCasterWindowsGetCoarserMaps) {
    // max_texel: each light's maps are the smallest multiple of 128 from 256 whose texel, the
    // casters' window from the light's centre over the side, is at most max_texel per unit
    // distance. adaptive_ball's ball spans about 0.4 (tangent units) from the light: 256 maps at
    // 0.002; the random scene behind tilted_light_union.json spans the 80-degree clamp (6.0):
    // map_size. The default is 0.002; at 0 every map is map_size's.
    const std::vector<penumbra::scene::Override> small = {{"image.width", "160"},
                                                          {"image.height", "120"}};
    const std::string coarser = R"({"name": "adaptive")";
    const auto coarse = render("adaptive_ball.json", coarser + "}", small);
    const auto full =
        render("adaptive_ball.json", R"({"name": "adaptive", "max_texel": 0})", small);
    EXPECT_EQ(coarse.stats.value("map_size", 0), 256);
    EXPECT_EQ(full.stats.value("map_size", 0), 1024);
    EXPECT_EQ(render("tilted_light_union.json", coarser + "}", small).stats.value("map_size", 0),
              1024);
    EXPECT_EQ(render("adaptive_ball.json", coarser + R"(, "map_size": 200})", small)
                  .stats.value("map_size", 0),
              200);  // a map_size below 256 is kept
    // On this floating ball the coarser maps cost little accuracy: within 0.001 of the 1024
    // maps' error against exact (measured 0.0086 against 0.0082, printed below).
    const auto truth = render("adaptive_ball.json", penumbra::testing::kGroundTruth, small);
    const double mae_coarse = shadowRegionMae(coarse.visibility, truth.visibility);
    const double mae_full = shadowRegionMae(full.visibility, truth.visibility);
    std::printf("adaptive_ball at 160x120: 256 maps %.5f, 1024 maps %.5f\n", mae_coarse, mae_full);
    EXPECT_LE(mae_coarse, mae_full + 0.001);
}

TEST(AdaptiveGL, SplitsAreTestedOnlyInTheScreenTilesWhereTheyDisagree) {
    // refine_tile: a split cell's new maps are tested, and its children weighted, only in the
    // tiles around the pixels where its corners disagreed. A box's wide penumbra and a thin
    // bar's far from it: at 16-pixel tiles each split of one is not tested around the other,
    // and the image is as the whole image's refinement (measured: the same floats, with 31% of
    // the view-tile tests).
    const auto truth = render("adaptive_two_shadows.json", penumbra::testing::kGroundTruth);
    const auto whole = render("adaptive_two_shadows.json", adaptive());
    const auto tiled = render("adaptive_two_shadows.json", adaptive(R"(, "refine_tile": 16)"));
    const double share = tiled.stats.value("tested_tile_share", 1.0);
    const double mae_whole = shadowRegionMae(whole.visibility, truth.visibility);
    const double mae_tiled = shadowRegionMae(tiled.visibility, truth.visibility);
    std::printf("two shadows: %.3f of view-tile pairs tested; MAE %.5f (whole %.5f)\n", share,
                mae_tiled, mae_whole);
    EXPECT_EQ(whole.stats.value("tested_tile_share", 0.0), 1.0);  // the default: one tile
    EXPECT_LT(share, 0.5);
    EXPECT_LE(mae_tiled, mae_whole + 0.0005);
    EXPECT_LE(penumbra::testing::maxAbsDifference(tiled.visibility, whole.visibility), 0.05);
}

TEST(AdaptiveGL, TilesWhereACastersOwnSurfaceCutsTheLightAreRefinedByEverySplit) {
    // A light grazing a post's face: which part of the light the face hides changes across the
    // light, which the maps' bits, where the comparisons look, do not show. Those tiles are
    // refined by every split; without that, 8-pixel tiles left the face at its corner maps'
    // blocks (0.0183 against 0.0091, measured before the rule), with it the same floats.
    const auto truth = render("adaptive_grazing.json", penumbra::testing::kGroundTruth);
    const auto whole = render("adaptive_grazing.json", adaptive());
    const auto tiled = render("adaptive_grazing.json", adaptive(R"(, "refine_tile": 8)"));
    const double mae_whole = shadowRegionMae(whole.visibility, truth.visibility);
    const double mae_tiled = shadowRegionMae(tiled.visibility, truth.visibility);
    std::printf("grazing: MAE %.5f tiled, %.5f whole; %.3f of view-tile pairs tested\n", mae_tiled,
                mae_whole, tiled.stats.value("tested_tile_share", 1.0));
    EXPECT_LE(mae_tiled, mae_whole + 0.0005);
    EXPECT_LT(tiled.stats.value("tested_tile_share", 1.0), 0.5);
}
