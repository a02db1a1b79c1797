// `bitmask` (Schwarz & Stamminger) on small scenes: accuracy against `reference` N = 32 on the
// default scene, classification without back-projection, budgets and their statistics, budget
// maps (procedural and from an image), the acceleration structures and the area-accumulation
// alternative.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <OpenImageIO/imageio.h>

#include "gl_test_env.h"
#include "renderer/core/error.h"

using penumbra::testing::channel;
using penumbra::testing::renderScene;

namespace {

// The bitmask technique block with EXTRA keys (JSON members, comma-led).
std::string bitmask(const std::string& extra = "") {
    return R"({"name": "bitmask", "map_size": 256)" + extra + "}";
}

const std::vector<float>& truthOf(const std::string& scene) {
    static std::string cached_scene;
    static std::vector<float> cached;
    if (cached_scene != scene) {
        // Still `reference` N = 32, the truth these bounds were set against: against `exact`
        // the image-wide error of unlimited bitmask is 0.062, not 0.03, because on the objects'
        // own grazing surfaces it counts light as visible that exact's rays find behind the
        // surface (floor alone: 0.0063). The conformance issue moves this to `exact`.
        auto ref = renderScene(scene, {{"technique", R"({"name": "reference", "samples": 32,
                                                         "map_size": 512})"}});
        cached = channel(ref, "visibility");
        cached_scene = scene;
    }
    return cached;
}

struct Run {
    penumbra::output::Image image;
    nlohmann::json stats;
    double mae = 0;
};

Run run(const std::string& scene, const std::string& technique) {
    Run r;
    r.image = renderScene(scene, {{"technique", technique}}, 0, &r.stats);
    r.mae = penumbra::testing::shadowRegionMae(channel(r.image, "visibility"), truthOf(scene));
    return r;
}

}  // namespace

TEST(BitmaskGL, UnlimitedBudgetMatchesReferenceOnDefaultScene) {
    auto r = run("adaptive_default.json", bitmask(R"(, "budget": 0)"));
    std::printf(
        "bitmask unlimited, 256 bits, map 256, default scene: MAE %.5f; %.1f%% "
        "back-project, %.1f +- %.1f micro-occluders\n",
        r.mae, 100.0 * r.stats.value("backprojecting_share", 0.0),
        r.stats.value("micro_occluders_mean", 0.0), r.stats.value("micro_occluders_stddev", 0.0));
    // The issue's bound for unlimited budget and the 256-bit jittered bitmask.
    EXPECT_LE(r.mae, 0.03);
}

TEST(BitmaskGL, ClassesNeedNoBackprojectionAndMatchTheReference) {
    // The MSSM's tight depth ranges find umbra that the HSM's 2 x 2 coarse queries miss.
    auto r = run("adaptive_default.json", bitmask(R"(, "budget": 0, "accel": "mssm")"));
    const auto& cls = channel(r.image, "bitmask.class");
    const auto& vis = channel(r.image, "visibility");
    const auto& occ = channel(r.image, "bitmask.occluders");
    const auto& truth = truthOf("adaptive_default.json");
    long lit = 0, lit_wrong = 0, umbra = 0, umbra_wrong = 0, penumbra = 0;
    double occluders = 0;
    for (size_t i = 0; i < cls.size(); ++i) {
        if (cls[i] == 0.0f) {
            ++lit;
            lit_wrong += truth[i] < 0.95f;
            EXPECT_EQ(vis[i], 1.0f);
            EXPECT_EQ(occ[i], 0.0f);
        } else if (cls[i] == 2.0f) {
            ++umbra;
            umbra_wrong += truth[i] > 0.05f;
            EXPECT_EQ(vis[i], 0.0f);
        } else {
            ++penumbra;
            occluders += occ[i];
        }
    }
    std::printf(
        "lit %ld (%ld below 0.95 in the reference), umbra %ld (%ld above 0.05), "
        "penumbra %ld\n",
        lit, lit_wrong, umbra, umbra_wrong, penumbra);
    EXPECT_GT(umbra, 100);
    EXPECT_GT(lit, 1000);
    // Classification is exact for the shadow map's occluders; what differs from the reference
    // is the map's own texel-sized silhouette and normal-offset error: a 1 % allowance.
    EXPECT_LE(lit_wrong, lit / 100);
    EXPECT_LE(umbra_wrong, umbra / 100 + 1);
    // The statistics count exactly the penumbra pixels and their micro-occluders.
    EXPECT_EQ(r.stats.value("backprojecting_pixels", 0.0), double(penumbra));
    EXPECT_EQ(r.stats.value("umbra_pixels", 0.0), double(umbra));
    EXPECT_NEAR(r.stats.value("micro_occluders_mean", 0.0), occluders / double(penumbra), 1e-3);
    EXPECT_NEAR(r.stats.value("backprojecting_share", 0.0), double(penumbra) / double(cls.size()),
                1e-9);
}

TEST(BitmaskGL, BudgetBoundsMicroOccludersPerPixel) {
    double last_mean = 1e9;
    for (int budget : {0, 12, 8, 5}) {
        auto r = run("adaptive_default.json",
                     bitmask(R"(, "smooth": false, "budget": )" + std::to_string(budget)));
        const auto& occ = channel(r.image, "bitmask.occluders");
        const auto& b = channel(r.image, "bitmask.budget");
        const auto& level = channel(r.image, "bitmask.level");
        float most = 0;
        for (size_t i = 0; i < occ.size(); ++i) {
            most = std::max(most, occ[i]);
            EXPECT_EQ(b[i], float(budget));
            EXPECT_EQ(level[i], std::round(level[i]));  // integer levels without smoothing
        }
        const double mean = r.stats.value("micro_occluders_mean", 0.0);
        std::printf(
            "budget %d: MAE %.5f, %.1f%% back-project, %.1f +- %.1f micro-occluders "
            "(max %.0f)\n",
            budget, r.mae, 100.0 * r.stats.value("backprojecting_share", 0.0), mean,
            r.stats.value("micro_occluders_stddev", 0.0), most);
        if (budget > 0) {
            EXPECT_LE(most, float(budget * budget));
        }
        EXPECT_LT(mean, last_mean);
        last_mean = mean;
    }
}

namespace {
// Sum over the image of the part of |grad V_test| that exceeds |grad V_ref| (forward
// differences): seams and steps the reference does not have.
double excessGradient(const std::vector<float>& test, const std::vector<float>& ref, int width) {
    const int height = static_cast<int>(test.size()) / width;
    double sum = 0;
    for (int y = 0; y + 1 < height; ++y)
        for (int x = 0; x + 1 < width; ++x) {
            auto grad = [&](const std::vector<float>& v) {
                const size_t i = size_t(y) * size_t(width) + size_t(x);
                return std::hypot(double(v[i + 1] - v[i]), double(v[i + size_t(width)] - v[i]));
            };
            sum += std::max(0.0, grad(test) - grad(ref));
        }
    return sum;
}
}  // namespace

TEST(BitmaskGL, SmoothingLowersErrorAndSeamsAtBudget5) {
    auto off = run("adaptive_default.json", bitmask(R"(, "budget": 5, "smooth": false)"));
    auto on = run("adaptive_default.json", bitmask(R"(, "budget": 5, "smooth": true)"));
    const auto& truth = truthOf("adaptive_default.json");
    const int width = 192;
    const double seams_off = excessGradient(channel(off.image, "visibility"), truth, width);
    const double seams_on = excessGradient(channel(on.image, "visibility"), truth, width);
    std::printf("budget 5: MAE smooth off %.5f, on %.5f; excess gradient off %.2f, on %.2f\n",
                off.mae, on.mae, seams_off, seams_on);
    EXPECT_LT(on.mae, off.mae);
    EXPECT_LT(seams_on, seams_off);
    // Smoothed levels are fractional somewhere: blending happens.
    long fractional = 0;
    for (float l : channel(on.image, "bitmask.level")) fractional += l != std::round(l);
    EXPECT_GT(fractional, 100);
}

TEST(BitmaskGL, AccelerationStructuresAgree) {
    auto hsm = run("adaptive_default.json", bitmask(R"(, "budget": 0, "accel": "hsm")"));
    auto mssm = run("adaptive_default.json", bitmask(R"(, "budget": 0, "accel": "mssm")"));
    auto ysm =
        run("adaptive_default.json", bitmask(R"(, "budget": 0, "accel": "ysm", "ysm_size": 64)"));
    const double share_hsm = hsm.stats.value("backprojecting_share", 0.0);
    const double share_mssm = mssm.stats.value("backprojecting_share", 0.0);
    const double share_ysm = ysm.stats.value("backprojecting_share", 0.0);
    std::printf("back-projecting share: hsm %.4f, mssm %.4f, ysm %.4f; MAE %.5f %.5f %.5f\n",
                share_hsm, share_mssm, share_ysm, hsm.mae, mssm.mae, ysm.mae);
    // Tighter depth ranges prune more pixels: MSSM <= YSM <= HSM.
    EXPECT_LE(share_mssm, share_ysm);
    EXPECT_LE(share_ysm, share_hsm);
    // The pruning only decides which pixels skip back-projection, so the images agree; pixels
    // an MSSM calls umbra where the HSM back-projects differ by the micropatch gaps left.
    EXPECT_NEAR(mssm.mae, hsm.mae, 0.003);
    EXPECT_NEAR(ysm.mae, hsm.mae, 0.003);
}

TEST(BitmaskGL, BitmaskAvoidsTheOverOcclusionOfAreaSums) {
    auto bits = run("adaptive_default.json", bitmask(R"(, "budget": 0)"));
    auto area = run("adaptive_default.json", bitmask(R"(, "budget": 0, "visibility": "area")"));
    std::printf("unlimited: MAE bitmask %.5f, area %.5f\n", bits.mae, area.mae);
    EXPECT_LT(bits.mae, area.mae);
    // Overlapping back-projections are counted twice by area sums: darker on average.
    double sum_bits = 0, sum_area = 0;
    for (float v : channel(bits.image, "visibility")) sum_bits += v;
    for (float v : channel(area.image, "visibility")) sum_area += v;
    EXPECT_LT(sum_area, sum_bits);
}

TEST(BitmaskGL, BudgetFalloffMap) {
    auto r = renderScene("adaptive_default.json",
                         {{"technique", bitmask(R"(, "budget": 12, "budget_falloff": true,
                                                   "budget_edge": 5)")}});
    const auto& b = channel(r, "bitmask.budget");
    const int w = 192, h = 144;
    EXPECT_EQ(b[size_t(h / 2) * w + w / 2], 12.0f);  // the centre
    EXPECT_EQ(b[0], 5.0f);                           // a corner
    EXPECT_EQ(b[size_t(h - 1) * w + w - 1], 5.0f);
}

TEST(BitmaskGL, BadParametersAreInputErrors) {
    for (const char* extra :
         {R"(, "map_size": 200)", R"(, "budget": 1)", R"(, "bits": 100)",
          R"(, "map_size": 128, "ysm_size": 256)", R"(, "accel": "mssm", "map_size": 4096)"})
        EXPECT_THROW(renderScene("closed_form.json", {{"technique", bitmask(extra)}}),
                     penumbra::InputError)
            << extra;
}

TEST(BitmaskGL, MicrorectsBeatMicropatchesAtCoarseLevels) {
    // Budget 4 without smoothing: every penumbra pixel uses a coarse level (Fig. 12).
    const std::string coarse = R"(, "budget": 4, "smooth": false, "map_size": 512)";
    auto patches = run("adaptive_default.json", bitmask(coarse));
    auto rects = run("adaptive_default.json", bitmask(coarse + R"(, "occluders": "microrect")"));
    auto rects_area = run("adaptive_default.json",
                          bitmask(coarse + R"(, "occluders": "microrect", "visibility": "area")"));
    std::printf(
        "budget 4: MAE micropatches %.5f, microrects %.5f (area sums %.5f); "
        "%.1f micro-occluders per pixel\n",
        patches.mae, rects.mae, rects_area.mae, patches.stats.value("micro_occluders_mean", 0.0));
    EXPECT_LT(rects.mae, patches.mae);
}

TEST(BitmaskGL, LevelZeroMicrorectsAreMicropatches) {
    const std::string scene = "adaptive_default.json";
    auto patches = run(scene, bitmask(R"(, "budget": 0, "gap_fill": false)")).image;
    auto rects = run(scene, bitmask(R"(, "budget": 0, "occluders": "microrect")")).image;
    // At level 0 a microrect is its texel with the texel's depth: the same rectangles. Their far
    // edges are computed as lo + (x + 1) t instead of (lo + x t) + t, a float rounding that can
    // move an edge across one light sample: at most 1 of 256 bits.
    EXPECT_LE(penumbra::testing::maxAbsDifference(channel(patches, "visibility"),
                                                  channel(rects, "visibility")),
              1.0 / 256.0 + 1e-6);
}

TEST(BitmaskGL, MicroquadsUnderestimateWhereMicropatchesOverestimate) {
    auto quads =
        run("adaptive_default.json", bitmask(R"(, "budget": 0, "occluders": "microquad")"));
    auto patches = run("adaptive_default.json", bitmask(R"(, "budget": 0)"));
    double lit_quads = 0, lit_patches = 0;
    for (float v : channel(quads.image, "visibility")) lit_quads += v;
    for (float v : channel(patches.image, "visibility")) lit_patches += v;
    std::printf("unlimited: MAE microquads %.5f, micropatches %.5f; %.1f microquads per pixel\n",
                quads.mae, patches.mae, quads.stats.value("micro_occluders_mean", 0.0));
    // Section 5.1: quads between texel centres end half a texel inside every silhouette, so
    // they occlude less than micropatches (measured MAE 0.051 against 0.026); the bound leaves
    // 0.01 for the reference's jitter and the edge tables' 0.01 quantisation.
    EXPECT_GT(lit_quads, lit_patches);
    EXPECT_LE(quads.mae, 0.06);
    EXPECT_THROW(
        renderScene("closed_form.json", {{"technique", bitmask(R"(, "occluders": "microquad",
                                                       "visibility": "area")")}}),
        penumbra::InputError);
}

namespace {
// The mean visibility step |V(a) - V(b)| over neighbouring pixel pairs of which one was called
// lit without back-projection and the other back-projected: the lit interface of section 6.
double litInterfaceStep(const penumbra::output::Image& img, int width) {
    const auto& v = channel(img, "visibility");
    const auto& cls = channel(img, "bitmask.class");
    double sum = 0;
    long n = 0;
    for (size_t i = 0; i + size_t(width) < v.size(); ++i)
        for (size_t j : {i + 1, i + size_t(width)})
            if ((cls[i] == 0.0f && cls[j] == 1.0f) || (cls[i] == 1.0f && cls[j] == 0.0f)) {
                sum += std::fabs(double(v[i]) - double(v[j]));
                ++n;
            }
    EXPECT_GT(n, 100);
    return n ? sum / double(n) : 0.0;
}
}  // namespace

TEST(BitmaskGL, GrowingQueriesAvoidsOverPrecisionSeams) {
    const std::string base = R"(, "budget": 5, "smooth": false, "accel": "mssm")";
    auto grown = run("adaptive_default.json", bitmask(base));
    auto exact = run("adaptive_default.json", bitmask(base + R"(, "grow_query": false)"));
    const double step_grown = litInterfaceStep(grown.image, 192);
    const double step_exact = litInterfaceStep(exact.image, 192);
    std::printf(
        "budget 5, mssm: grown queries MAE %.5f, lit-interface step %.4f; exact queries "
        "MAE %.5f, lit-interface step %.4f\n",
        grown.mae, step_grown, exact.mae, step_exact);
    // Section 6: exact queries call pixels lit that a coarse micro-occluder of their level would
    // still reach, so visibility jumps where the lit region begins (measured 0.24 mean step);
    // grown queries back-project there and the step shrinks (0.19; what is left comes from
    // neighbours choosing different levels without smoothing). The overall error is not lower
    // (0.218 against 0.209): the extra pixels get the coarse micropatches' overestimate.
    EXPECT_LT(step_grown, step_exact);
}

TEST(BitmaskGL, BudgetMapImage) {
    // tests/data/gl/budget_halves.png (64 x 8): 0 on its left half, 1 on its right, stretched
    // bilinearly over the 192 pixels: b_mo = budget_edge on the left, budget on the right, and
    // a ramp over the 3 pixels around the middle where the two map texels blend.
    auto r = renderScene("adaptive_default.json",
                         {{"technique", bitmask(R"(, "budget": 12, "budget_edge": 5,
                                                   "budget_map": "budget_halves.png")")}});
    const auto& b = channel(r, "bitmask.budget");
    const int w = 192, h = 144;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const float v = b[size_t(y) * w + size_t(x)];
            if (x < w / 2 - 2) {
                ASSERT_EQ(v, 5.0f) << x << ", " << y;
            }
            if (x >= w / 2 + 2) {
                ASSERT_EQ(v, 12.0f) << x << ", " << y;
            }
            if (x > 0) {
                ASSERT_GE(v, b[size_t(y) * w + size_t(x) - 1]);  // no step back
            }
        }
    // With the falloff too the map scales the falloff's budget: the centre of the right half
    // keeps nearly `budget`, the right corners fall to budget_edge, the left half stays there.
    auto both = renderScene("adaptive_default.json",
                            {{"technique", bitmask(R"(, "budget": 12, "budget_edge": 5,
                                                      "budget_falloff": true,
                                                      "budget_map": "budget_halves.png")")}});
    const auto& bb = channel(both, "bitmask.budget");
    EXPECT_EQ(bb[size_t(h / 2) * w + w / 2 + 4], 12.0f);
    EXPECT_EQ(bb[size_t(h - 1) * w + w - 1], 5.0f);
    EXPECT_EQ(bb[size_t(h / 2) * w + 10], 5.0f);
    // The image's top row is the top of the screen: an EXR (absolute path) bright on top.
    const char* tmp = std::getenv("PENUMBRA_TEST_TMP");
    const std::string top = std::string(tmp ? tmp : "/tmp") + "/budget_top.exr";
    {
        std::vector<float> pixels(8 * 64, 0.0f);
        std::fill(pixels.begin(), pixels.begin() + 8 * 32, 1.0f);  // rows 0-31: the top half
        auto out = OIIO::ImageOutput::create(top);
        ASSERT_TRUE(out);
        ASSERT_TRUE(out->open(top, OIIO::ImageSpec(8, 64, 1, OIIO::TypeDesc::HALF)));
        ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, pixels.data()));
        out->close();
    }
    auto vertical = renderScene("adaptive_default.json",
                                {{"technique", bitmask(R"(, "budget": 12, "budget_edge": 5,
                                                          "budget_map": ")" +
                                                       top + "\"")}});
    const auto& bv = channel(vertical, "bitmask.budget");
    EXPECT_EQ(bv[size_t(10) * w + w / 2], 12.0f);
    EXPECT_EQ(bv[size_t(h - 10) * w + w / 2], 5.0f);
    // A missing map is an input error naming the key.
    try {
        renderScene("adaptive_default.json",
                    {{"technique", bitmask(R"(, "budget_map": "missing.png")")}});
        FAIL() << "expected an InputError";
    } catch (const penumbra::InputError& e) {
        EXPECT_NE(std::string(e.what()).find("technique.budget_map: "), std::string::npos)
            << e.what();
    }
}
