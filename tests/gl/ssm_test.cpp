// `ssm` (soft shadow maps, Atty et al. 2006) on floating square occluders (closed_form.json,
// ssm_tilted.json): accuracy against `reference` and the closed form, trends of 5.2, variants.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "gl_test_env.h"
#include "renderer/core/error.h"
#include "renderer/core/light_geometry.h"

using penumbra::testing::channel;
using penumbra::testing::renderScene;

namespace {

// The ssm technique block with EXTRA keys (JSON members, comma-led).
std::string ssm(const std::string& extra = "") {
    return R"({"name": "ssm")" + extra + "}";
}

double shadowMae(const penumbra::output::Image& ref, const penumbra::output::Image& test) {
    return penumbra::testing::floorShadowMae(ref, test);
}

// The same against the closed form of closed_form.json with a light of half size HALF.
double closedFormMae(const penumbra::output::Image& img, double half) {
    return penumbra::testing::closedFormShadowMae(img, half, 500);
}

// closed_form.json's occluder replaced by a tilted box: patches of many depths whose quads
// overlap, and far faces hidden from the light's centre.
const penumbra::scene::Override kTiltedBox = {
    "objects.1", R"({"name": "occluder", "box": {"size": [0.6, 0.8, 0.6]},
                     "transform": {"translate": [0.2, 1.3, 0.1], "rotate": [30, 0, 20]},
                     "shadow": "occluder"})"};

// closed_form.json with the tilted box, rendered with the technique block TECHNIQUE.
penumbra::output::Image tiltedBox(const std::string& technique) {
    return renderScene("closed_form.json", {kTiltedBox, {"technique", technique}});
}

}  // namespace

TEST(SsmGL, MatchesReferenceOnFloatingOccluder) {
    auto ref = renderScene("closed_form.json", {{"technique", penumbra::testing::kGroundTruth}});
    auto test = renderScene("closed_form.json",
                            {{"technique", ssm(R"(, "map_size": 256, "ssm_size": 64)")}});
    const double mae = shadowMae(ref, test);
    std::printf("ssm 256 vs exact N=32: shadow-region MAE %.5f\n", mae);
    // The issue's bound: 0.05 at a 256 x 256 occluder map and a 1 x 1 light (paper, 5.2).
    EXPECT_LE(mae, 0.05);
}

TEST(SsmGL, ErrorGrowsWithLightSize) {
    // A tilted square, not the parallel one: micro-patches of a plane parallel to the light all
    // lie at one depth (dh = 0 in eq. 1), so their back-projections never overlap or gap.
    double previous = 0.0, area = 0.0, samples = 0.0;
    for (double size : {0.5, 1.0, 2.0}) {
        std::string light = "[";  // built by += (GCC 12's -Wrestrict misfires on "[" + string)
        light += std::to_string(size) + "," + std::to_string(size) + "]";
        auto ref = renderScene("ssm_tilted.json", {{"lights.0.size", light}});
        auto with = [&](const char* accumulate) {
            return shadowMae(ref,
                             renderScene("ssm_tilted.json",
                                         {{"technique", ssm(R"(, "map_size": 64, "ssm_size": 64, )"
                                                            R"("accumulate": ")" +
                                                            std::string(accumulate) + "\"")},
                                          {"lights.0.size", light}}));
        };
        area = with("area");
        samples = with("samples");
        std::printf("ssm 64 tilted square, light %.1f: shadow-region MAE area %.5f, samples %.5f\n",
                    size, area, samples);
        // The paper's sum: overlaps and gaps of back-projected micro-patches grow with the
        // light (eq. 3).
        EXPECT_GT(area, previous);
        previous = area;
    }
    // The sample masks count the overlaps once and the seal closes the gaps, so the error no
    // longer grows: measured 0.0121 / 0.0116 / 0.0090 against the sum's 0.0166 / 0.0265 /
    // 0.0391 at 0.5 / 1 / 2 m.
    EXPECT_LT(samples, 0.5 * area);
}

TEST(SsmGL, ErrorFallsWithMapSizeThenLevelsOff) {
    auto ref = renderScene("ssm_tilted.json", {});
    double mae[3];
    const int sizes[3] = {16, 64, 256};
    for (int i = 0; i < 3; ++i) {
        auto test = renderScene("ssm_tilted.json",
                                {{"technique", ssm(", \"map_size\": " + std::to_string(sizes[i]) +
                                                   R"(, "ssm_size": 64)")}});
        mae[i] = shadowMae(ref, test);
        std::printf("ssm tilted square, map %d: shadow-region MAE %.5f\n", sizes[i], mae[i]);
    }
    // Finer micro-patches halve dh (eq. 3) and the silhouette's half-texel error (5.1.1)...
    EXPECT_GT(mae[0], mae[1] + 0.003);
    // ...until the overlap of neighbouring back-projections dominates: the curve is flat
    // within 0.003 (a tenth of the error) from 64 to 256 (paper, 5.2.3).
    EXPECT_NEAR(mae[2], mae[1], 0.003);
}

TEST(SsmGL, TwoSidedHelpsOnABox) {
    // A tilted box: its far faces, hidden from the light's centre, shadow parts of the floor
    // that the near faces' micro-patches miss (3.5, Fig. 10).
    auto ref = renderScene("closed_form.json", {kTiltedBox});
    auto with = [](const std::string& extra) {
        return tiltedBox(ssm(R"(, "map_size": 64, "ssm_size": 64)" + extra));
    };
    const double one = shadowMae(ref, with(R"(, "two_sided": false)")),
                 two = shadowMae(ref, with(R"(, "two_sided": true)"));
    std::printf("ssm 64 box: shadow-region MAE one-sided %.5f, two-sided %.5f\n", one, two);
    EXPECT_LT(two, one);
}

TEST(SsmGL, CpuPathEqualsGpuPathToTheByte) {
    // The GPU path lists the micro-patches in the CPU path's row-major order (compact.comp's
    // prefix sum over groups), and the splats blend in list order, so both paths sum the same
    // terms in the same order: equal bits, run after run. Under the earlier atomic-counter list
    // they differed in the last bits (4e-7 on the tilted box).
    auto with = [](const char* path) {
        return tiltedBox(
            ssm(R"(, "map_size": 64, "ssm_size": 64, "path": ")" + std::string(path) + R"(")"));
    };
    const auto gpu = with("gpu"), cpu = with("cpu"), again = with("gpu");
    for (const char* c : {"visibility", "R", "G", "B"}) {
        EXPECT_EQ(penumbra::testing::maxAbsDifference(channel(gpu, c), channel(cpu, c)), 0.0) << c;
        EXPECT_EQ(penumbra::testing::maxAbsDifference(channel(gpu, c), channel(again, c)), 0.0)
            << c;
    }
}

TEST(SsmGL, AFlatOccluderAtAnyHeightCastsItsShadow) {
    // A square parallel to the light lies at the occluder window's nearest depth, and the floor
    // at the receivers'; the windows' near planes sat exactly there, so at most heights the
    // rasteriser clipped the square (no micro-patch: a lit floor) or, with layers 1, the floor
    // (no receiver). The windows now keep a margin before their nearest depth.
    for (const char* y : {"1.0", "1.4"})
        for (const char* layers : {"1", "4"}) {
            const penumbra::scene::Override moved = {"objects.1.transform.translate",
                                                     std::string("[0.2, ") + y + ", 0.1]"};
            const auto ref = renderScene("closed_form.json", {moved});
            const auto img = renderScene(
                "closed_form.json",
                {moved,
                 {"technique",
                  ssm(R"(, "map_size": 64, "ssm_size": 64, "layers": )" + std::string(layers))}});
            const double mae = shadowMae(ref, img);
            std::printf("ssm 64, square at height %s, layers %s: shadow-region MAE %.4f\n", y,
                        layers, mae);
            EXPECT_LE(mae, 0.02) << "height " << y << ", layers " << layers;
        }
}

TEST(SsmGL, TwoSidedEqualsOneSidedForAFlatOccluder) {
    auto one = renderScene(
        "closed_form.json",
        {{"technique", ssm(R"(, "map_size": 64, "ssm_size": 64, "two_sided": false)")}});
    auto two =
        renderScene("closed_form.json",
                    {{"technique", ssm(R"(, "map_size": 64, "ssm_size": 64, "two_sided": true)")}});
    const auto& v1 = channel(one, "visibility");
    const auto& v2 = channel(two, "visibility");
    const double max = penumbra::testing::maxAbsDifference(v1, v2);
    // A plane's nearest and farthest surfaces are the same texels at the same depths.
    EXPECT_LE(max, 1e-5);
}

TEST(SsmGL, Fp32RemovesTheFp16ArtefactAt512) {
    // The paper's sum (accumulate=area): the sample masks do not blend.
    const std::string base = R"(, "map_size": 512, "ssm_size": 48, "accumulate": "area")";
    auto fp32 = renderScene("closed_form.json", {{"technique", ssm(base)}});
    auto fp16 =
        renderScene("closed_form.json", {{"technique", ssm(base + R"(, "precision": "fp16")")}});
    const double e32 = closedFormMae(fp32, 0.5), e16 = closedFormMae(fp16, 0.5);
    std::printf("ssm 512: closed-form MAE fp32 %.5f, fp16 %.5f\n", e32, e16);
    // Appendix A: at 512^2 each micro-patch adds less than half an fp16 ulp of the sums near
    // the umbra, so fp16 sums stall; fp32 keeps them within the 0.05 bound.
    EXPECT_LE(e32, 0.05);
    EXPECT_GT(e16, 2.0 * e32);
}

TEST(SsmGL, SamplesEqualAreaWhereBackProjectionsTile) {
    // closed_form.json's square is parallel to the light: its micro-patches share one depth, so
    // their back-projections tile the light without overlap (dh = 0 in eq. 1) and the union of
    // accumulate=samples is the paper's sum. What differs is the 256 samples' quantisation.
    const std::string base = R"(, "map_size": 128, "ssm_size": 64, "two_sided": false)";
    auto area =
        renderScene("closed_form.json", {{"technique", ssm(base + R"(, "accumulate": "area")")}});
    auto samples = renderScene("closed_form.json",
                               {{"technique", ssm(base + R"(, "accumulate": "samples")")}});
    const double e_area = closedFormMae(area, 0.5), e_samples = closedFormMae(samples, 0.5);
    const double max = penumbra::testing::maxAbsDifference(channel(area, "visibility"),
                                                           channel(samples, "visibility"));
    std::printf("ssm 128, flat square: closed-form MAE area %.5f, samples %.5f; max diff %.4f\n",
                e_area, e_samples, max);
    // A rectangle of the light holds its area's share of the 256 samples to within a few
    // samples (measured: MAE 0.0075 against the closed form, max 0.0285, 7 samples); a wrong
    // row or column mask would miss whole rows of 16.
    EXPECT_LE(e_samples, e_area + 0.01);
    EXPECT_LE(max, 0.04);
}

TEST(SsmGL, SamplesCountOverlappingBackProjectionsOnce) {
    // light_low: a 0.35 m ball 0.15 m under a 1 m light. Seen from the floor beneath it, the
    // far side's micro-patches near the silhouette (seen from the light's centre) back-project
    // onto overlapping parts of the light, and the near side's onto the far side's: the paper's
    // sum (5.1.2) makes the umbra too large and dark in a ring. The sample masks count each
    // part of the light once; where neighbours at different depths leave gaps between their
    // back-projections, the union lets light through that the sum's overlaps had offset, and
    // `seal` closes them. The gaps are the micro-patches' (lod 0): a merged block (`lod`) is a
    // plane through its micro-patches, without gaps inside it.
    const std::string scene = "../../../scenes/conformance/light_low.json";
    auto with = [&](const std::string& technique) {
        return renderScene(
            scene, {{"image.width", "128"}, {"image.height", "96"}, {"technique", technique}});
    };
    const auto exact = with(penumbra::testing::kGroundTruth);
    const std::string small = R"(, "map_size": 128, "ssm_size": 96)";
    const double area = shadowMae(exact, with(ssm(small + R"(, "accumulate": "area")")));
    const double samples = shadowMae(exact, with(ssm(small)));
    const double sealed = shadowMae(exact, with(ssm(small + R"(, "lod": 0)")));
    const double unsealed = shadowMae(exact, with(ssm(small + R"(, "lod": 0, "seal": 0)")));
    std::printf(
        "ssm, light_low floor: shadow-region MAE area %.4f, samples %.4f (lod 0: %.4f, "
        "with seal 0: %.4f)\n",
        area, samples, sealed, unsealed);
    // Measured 0.0846, 0.0101, 0.0123 and 0.0497 (the corpus at 320 x 240, defaults before
    // the planes: 0.085, 0.011, 0.051 with seal 0).
    EXPECT_LE(samples, 0.05);  // issue 15's floor bound
    EXPECT_LT(samples, 0.5 * area);
    EXPECT_LT(sealed, 0.5 * unsealed);
}

TEST(SsmGL, SceneWithoutOccludersIsAnInputError) {
    EXPECT_THROW(
        renderScene("closed_form.json", {{"technique", ssm()}, {"objects.1.shadow", "receiver"}}),
        penumbra::InputError);
    EXPECT_THROW(
        renderScene("closed_form.json", {{"technique", ssm()}, {"objects.0.shadow", "occluder"}}),
        penumbra::InputError);
}

TEST(SsmGL, OccluderBehindTheLightCastsNothing) {
    auto img =
        renderScene("closed_form.json", {{"technique", ssm(R"(, "map_size": 32)")},
                                         {"objects.1.transform.translate", "[0.2, 4, 0.1]"}});
    const auto& vis = channel(img, "visibility");
    const auto& id = channel(img, "id");
    long shadowed = 0;
    for (size_t i = 0; i < vis.size(); ++i) shadowed += id[i] == 0.0f && vis[i] != 1.0f;
    EXPECT_EQ(shadowed, 0);  // no micro-patch lies in front of the light: exactly lit
}

TEST(SsmGL, RectLightsOfEitherAspectMatchReference) {
    for (const char* size : {"[1.6, 0.5]", "[0.5, 1.6]"}) {
        auto ref = renderScene("closed_form.json", {{"lights.0.size", size}});
        auto test = renderScene(
            "closed_form.json",
            {{"technique", ssm(R"(, "map_size": 128, "ssm_size": 64)")}, {"lights.0.size", size}});
        const double mae = shadowMae(ref, test);
        std::printf("ssm 128, light %s: shadow-region MAE %.5f\n", size, mae);
        // A square parallel to the light is the exact case (dh = 0, eq. 1): what is left is the
        // half-texel silhouette error (5.1.1) and the reference's 16 x 16 sampling noise, about
        // 0.005 each; a swapped axis or aspect would give several times 0.02.
        EXPECT_LE(mae, 0.02);
    }
}

TEST(SsmGL, ClippingToReceiversKeepsTheImage) {
    auto with = [](const char* clip) {
        return tiltedBox(ssm(R"(, "map_size": 64, "ssm_size": 64, "clip": )" + std::string(clip)));
    };
    auto clipped = with("true"), full = with("false");
    const auto& vc = channel(clipped, "visibility");
    const auto& vf = channel(full, "visibility");
    const double max = penumbra::testing::maxAbsDifference(vc, vf);
    // Clipping drops only texels beyond every receiver's penumbra, whose coverage is zero up to
    // the rounding of 1/z_O - 1/z_R at the quad's border (about 1e-6 measured).
    EXPECT_LE(max, 1e-5);
}

TEST(SsmGL, FarReachKeepsTheContactShadowOfARestingBox) {
    // A box resting on the floor under the light's centre (conformance box_resting): its side
    // walls, back faces from the light's centre, fill the far-side map between its top's and
    // its bottom's outlines, each texel a flat patch at the wall's depth there. Those near the
    // wall's foot hovered just over the floor beside it and hid much of the light from it
    // (floor MAE 0.0025 one-sided, 0.0129 two-sided, measured here); with far_reach 8 a
    // far-side patch spares the receivers within its surface's reach (splat.vert): 0.0036.
    const std::vector<penumbra::scene::Override> box = {
        {"objects.1", R"({"name": "box", "box": {"size": [0.8, 0.8, 0.8]},
                          "transform": {"translate": [0, 0.4, 0], "rotate": [0, 30, 0]}})"},
        {"camera", R"({"position": [2.6, 2.4, 3.4], "target": [0, 0.4, 0], "up": [0, 1, 0],
                       "fov_y": 40, "near": 0.05, "far": 60})"}};
    auto with = [&](const std::string& technique) {
        auto o = box;
        o.push_back({"technique", technique});
        return renderScene("closed_form.json", o);
    };
    const auto ref = with(penumbra::testing::kGroundTruth);
    const double one = shadowMae(ref, with(ssm(R"(, "two_sided": false)"))),
                 two = shadowMae(ref, with(ssm(R"(, "two_sided": true, "far_reach": 8)")));
    std::printf("ssm resting box: floor shadow-region MAE one-sided %.5f, two-sided %.5f\n", one,
                two);
    EXPECT_LE(two, one + 0.003);
}
