// `css` (convolution soft shadows, Annen et al. 2008) on the default scene and the floating
// square of closed_form.json: shadow-region error against `exact` N = 32 and the closed
// form, contact shadows, mipmap and SAT prefiltering, rectangular lights, diagnostics.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <utility>

#include "gl_test_env.h"

using penumbra::output::Image;
using penumbra::testing::channel;
using penumbra::testing::floorShadowMae;
using penumbra::testing::renderScene;

namespace {

// The css technique block with EXTRA keys (JSON members, comma-led).
std::string css(const std::string& extra = "") {
    return R"({"name": "css")" + extra + "}";
}

// The ground truth (`exact` N = 32) of SCENE (with OVERRIDES), rendered once per test binary.
const Image& truth(const std::string& scene, const std::string& light_size = "") {
    static std::map<std::string, Image> cache;
    const std::string key = scene + light_size;
    auto it = cache.find(key);
    if (it != cache.end()) return it->second;
    std::vector<penumbra::scene::Override> o = {{"technique", penumbra::testing::kGroundTruth}};
    if (!light_size.empty()) o.push_back({"lights.0.size", light_size});
    return cache.emplace(key, renderScene(scene, o)).first->second;
}

// Mean visibility over the floor pixels within 0.2 m of the pillar's footprint (0.12 m square
// at x = -0.9, z = 0.5 in the default scene) that REF has in shadow.
double contactMean(const Image& ref, const Image& img) {
    const auto& vr = channel(ref, "visibility");
    const auto& v = channel(img, "visibility");
    const auto& id = channel(ref, "id");
    const auto& px = channel(ref, "P.X");
    const auto& pz = channel(ref, "P.Z");
    double sum = 0;
    long n = 0;
    for (size_t i = 0; i < v.size(); ++i) {
        const double dx = std::max(std::fabs(px[i] + 0.9) - 0.06, 0.0);
        const double dz = std::max(std::fabs(pz[i] - 0.5) - 0.06, 0.0);
        if (id[i] != 0.0f || std::hypot(dx, dz) > 0.2 || vr[i] >= 0.999f) continue;
        sum += v[i];
        ++n;
    }
    EXPECT_GT(n, 20) << "the contact region should be visible";
    return n ? sum / static_cast<double>(n) : 1.0;
}

// Mean visibility of IMG over the pixels REF has in umbra (visibility 0), and their count.
std::pair<double, long> umbraMean(const Image& ref, const Image& img) {
    const auto& vr = channel(ref, "visibility");
    const auto& v = channel(img, "visibility");
    double sum = 0;
    long n = 0;
    for (size_t i = 0; i < v.size(); ++i) {
        if (vr[i] != 0.0f) continue;
        sum += v[i];
        ++n;
    }
    return {n ? sum / static_cast<double>(n) : 1.0, n};
}

}  // namespace

TEST(CssGL, DefaultSceneMatchesReference) {
    const Image& ref = truth("adaptive_default.json");
    for (const char* filter : {"mipmap", "sat"}) {
        auto img =
            renderScene("adaptive_default.json",
                        {{"technique", css(std::string(R"(, "filter": ")") + filter + "\"")}});
        const double mae = floorShadowMae(ref, img);
        std::printf("css %s, default scene: floor shadow-region MAE %.4f vs exact N=32\n", filter,
                    mae);
        // The issue's bound. Measured 0.054 (mipmap) and 0.055 (sat) at 192 x 144 with the
        // paper's blocker depth, 0.048 and 0.048 with the middle one (the default); the rest is
        // the single blocker depth per pixel (PCSS), wrong where blockers of very different
        // depths share a kernel (the pillar's long shadow). With the umbra's plateau divided
        // out (ring_plateau), 0.046 and 0.043.
        EXPECT_LE(mae, 0.06) << filter;
    }
}

TEST(CssGL, ContactShadowsAreNotLighterThanReference) {
    // With the paper's blocker depth (the nearest surface): the pillar's outline seen from the
    // light is its top, which that depth is. The middle of its top and foot (the default) is
    // bounded below.
    const Image& ref = truth("adaptive_default.json");
    const std::string nearest = R"(, "blocker_depth": "nearest")";
    auto sat = renderScene("adaptive_default.json", {{"technique", css(nearest)}});
    auto mip = renderScene("adaptive_default.json",
                           {{"technique", css(nearest + R"(, "filter": "mipmap")")}});
    auto unsharp =
        renderScene("adaptive_default.json", {{"technique", css(nearest + R"(, "sharpen_a": 0)")}});
    auto middle = renderScene("adaptive_default.json", {{"technique", css()}});
    const double r = contactMean(ref, ref), s = contactMean(ref, sat), m = contactMean(ref, mip),
                 u = contactMean(ref, unsharp), d = contactMean(ref, middle);
    std::printf(
        "pillar contact: reference %.3f, css sat %.3f, mipmap %.3f, without sharpening %.3f, "
        "middle blocker depth %.3f\n",
        r, s, m, u, d);
    // The middle blocker depth narrows the kernel of a caster whose outline is its top: its
    // foot comes out lighter. Measured 0.515 (0.045 over the reference); 0.398 since the
    // constant term of the CSM-Z series weights by the same depth (middle_at 0.35).
    EXPECT_LE(d, r + 0.06);
    // Measured 0.470 (reference), 0.444 (sat) and 0.509 (mipmap): 0.03 allows for the 53-pixel
    // sample's noise, 0.05 for the mipmaps' coarser blocker search (one trilinear tap per
    // layer); both catch the leak the paper's sharpening exists for (0.88 without it). Since the
    // map's window is fitted to each caster (finer texels on this scene of three casters),
    // 0.440 and 0.535, while the whole scene's receivers' error against `exact` fell (320 x 240:
    // sat 0.065 -> 0.051, mipmap 0.061 -> 0.057), so the mipmaps' allowance is 0.07.
    EXPECT_LE(s, r + 0.03);
    EXPECT_LE(m, r + 0.07);
    EXPECT_GT(u, s + 0.05) << "contact sharpening should darken the contact";
}

TEST(CssGL, FloatingSquareMatchesReferenceAndClosedForm) {
    const Image& ref = truth("closed_form.json");
    for (const char* filter : {"mipmap", "sat"}) {
        auto img =
            renderScene("closed_form.json",
                        {{"technique", css(std::string(R"(, "filter": ")") + filter + "\"")}});
        const double mae = floorShadowMae(ref, img);
        const double closed = penumbra::testing::closedFormShadowMae(img, 0.5, 500);
        std::printf("css %s, floating square: MAE %.4f vs reference, %.4f vs closed form\n", filter,
                    mae, closed);
        // A plane parallel to the light is PCSS's exact case: one blocker depth, a box kernel.
        // Measured 0.011 (mipmap: 2 x 2 trilinear taps approximate the box) and 0.008 (SAT);
        // with the umbra's plateau divided out (ring_plateau) 0.014 and 0.0017 (0.0000 against
        // the closed form).
        EXPECT_LE(mae, 0.025) << filter;
        EXPECT_LE(closed, 0.03) << filter;
    }
}

// blocker_depth: the blocker search on a ball under a wide light (the conformance scene
// light_size_2) averages the depth of the ball's middle, its silhouette's, instead of its top:
// the kernel narrows to what the ball's outline sets, and the shadow's core darkens.
TEST(CssGL, MiddleBlockerDepthNarrowsARoundCastersKernel) {
    const std::string wide = "[2, 2]";
    const Image& ref = truth("adaptive_ball.json", wide);
    auto nearest = renderScene(
        "adaptive_ball.json",
        {{"technique", css(R"(, "blocker_depth": "nearest")")}, {"lights.0.size", wide}});
    auto middle =
        renderScene("adaptive_ball.json", {{"technique", css()}, {"lights.0.size", wide}});
    const double n = floorShadowMae(ref, nearest), m = floorShadowMae(ref, middle);
    std::printf("css on a ball under a 2 m light: floor shadow MAE %.4f nearest, %.4f middle\n", n,
                m);
    // The conformance run of light_size_2 (receivers, 320 x 240) measured 0.0458 -> 0.0231.
    // Here 0.0525 -> 0.0262; 0.0506 -> 0.0233 with ring_plateau; 0.0506 -> 0.0158 with
    // middle_at 0.35 and the CSM-Z constant term at the same depth.
    EXPECT_LE(m, 0.6 * n);
    EXPECT_LE(m, 0.03);
}

// A flat caster's nearest and farthest surfaces are one: the middle is its depth, and the
// image is the paper's.
TEST(CssGL, MiddleBlockerDepthLeavesAFlatCasterAsItIs) {
    auto nearest =
        renderScene("closed_form.json", {{"technique", css(R"(, "blocker_depth": "nearest")")}});
    auto middle = renderScene("closed_form.json", {{"technique", css()}});
    EXPECT_EQ(channel(nearest, "visibility"), channel(middle, "visibility"));
}

// ring_plateau: the truncated series ripples about 1 past its step (0.961 at half the depth
// range with M = 4), so a plain umbra reads about 0.04; dividing the final test by the series'
// value at the kernel's mean caster depth makes it black. A ball under a 0.25 m light (the
// conformance scene light_size_0.25) has a wide umbra.
TEST(CssGL, UmbraIsBlackPastTheSeriesRipple) {
    const std::string small = "[0.25, 0.25]";
    const Image& ref = truth("adaptive_ball.json", small);
    auto plain = renderScene("adaptive_ball.json", {{"technique", css(R"(, "ring_plateau": 0)")},
                                                    {"lights.0.size", small}});
    auto img = renderScene("adaptive_ball.json", {{"technique", css()}, {"lights.0.size", small}});
    const auto [p, n] = umbraMean(ref, plain);
    const double v = umbraMean(ref, img).first;
    const double mae_plain = floorShadowMae(ref, plain), mae = floorShadowMae(ref, img);
    std::printf(
        "css, ball under a 0.25 m light: umbra (%ld pixels) %.4f plain, %.4f corrected; "
        "floor shadow MAE %.4f plain, %.4f corrected\n",
        n, p, v, mae_plain, mae);
    ASSERT_GT(n, 200) << "the umbra should be in view";
    // Measured here 0.0191 plain and 0.0002 corrected, floor MAE 0.0245 -> 0.0070 (the ripple's
    // value depends on the depths: the conformance scene's umbra 0.0387 -> 0.0000).
    EXPECT_GT(p, 0.01) << "the plain series' ripple should show (the test would be void)";
    EXPECT_LE(v, 0.005);
    EXPECT_LE(mae, 0.7 * mae_plain);
}

// With SATs, the pixels with no caster under their first search kernel are written by the
// marking draw (visibility_cover.frag) and interpolation is on by default; with mipmaps every
// pixel is evaluated by the stages (llvmpipe samples a per-pixel level lane by lane), so
// `interpolate` changes nothing there. Both ways, the floor (which casts nothing, so its
// horizon share is 1) reads exactly 1 wherever no blocker was found.
TEST(CssGL, MipmapsEvaluateEveryPixelAndSatsMarkTheLitOnes) {
    auto mip = renderScene("adaptive_default.json",
                           {{"technique", css(R"(, "filter": "mipmap", "interpolate": 0)")}});
    auto mip_interpolated =
        renderScene("adaptive_default.json",
                    {{"technique", css(R"(, "filter": "mipmap", "interpolate": 0.5)")}});
    EXPECT_EQ(penumbra::testing::maxAbsDifference(channel(mip, "visibility"),
                                                  channel(mip_interpolated, "visibility")),
              0.0);
    auto sat = renderScene("adaptive_default.json", {{"technique", css()}});
    for (const Image* img : {&mip, &sat}) {
        const auto& v = channel(*img, "visibility");
        const auto& z = channel(*img, "css.z_avg");
        const auto& id = channel(*img, "id");
        long lit = 0;
        for (size_t i = 0; i < v.size(); ++i) {
            if (id[i] != 0.0f || z[i] != 0.0f) continue;  // the floor (id 0), no blocker found
            EXPECT_EQ(v[i], 1.0f) << "pixel " << i;
            ++lit;
        }
        EXPECT_GT(lit, 5000) << "most of the floor is lit";
    }
}

TEST(CssGL, RectangularLightThroughSatAndAnisotropicMipmaps) {
    const std::string size = "[1.6,0.5]";
    const Image& ref = truth("closed_form.json", size);
    double mae[2];
    const char* filters[2] = {"auto", "mipmap"};
    for (int i = 0; i < 2; ++i) {
        auto img =
            renderScene("closed_form.json",
                        {{"technique", css(std::string(R"(, "filter": ")") + filters[i] + "\"")},
                         {"lights.0.size", size}});
        mae[i] = floorShadowMae(ref, img);
        std::printf("css %s, 1.6 x 0.5 light: MAE %.4f vs reference\n", filters[i], mae[i]);
    }
    // auto picks SATs for a rectangle: an exact box of the light's aspect; anisotropic mipmaps
    // (taps along the long axis) come close. Measured 0.0083 and 0.0090.
    EXPECT_LE(mae[0], 0.025);
    EXPECT_LE(mae[1], 0.03);
}

TEST(CssGL, OrderAndMapSizeAreHonoured) {
    const Image& ref = truth("closed_form.json");
    for (int order : {1, 2, 7, 16}) {
        auto img = renderScene("closed_form.json",
                               {{"technique", css(R"(, "order": )" + std::to_string(order))}});
        const double mae = floorShadowMae(ref, img);
        std::printf("css order %d: MAE %.4f\n", order, mae);
        // Measured 0.011, 0.018, 0.004 and 0.002 with a 256 map: the shift and clamp make even
        // a one-term series a clean enough step for a planar occluder far above the floor.
        EXPECT_LE(mae, 0.03) << order;
    }
    auto small = renderScene("closed_form.json", {{"technique", css(R"(, "map_size": 64)")}});
    EXPECT_LE(floorShadowMae(ref, small), 0.05);  // a wide penumbra needs few texels
}

TEST(CssGL, DiagnosticsDescribeTheKernel) {
    auto img = renderScene("closed_form.json", {{"technique", css()}});
    const auto& v = channel(img, "visibility");
    const auto& z = channel(img, "css.z_avg");
    const auto& w = channel(img, "css.filter_width");
    const auto& id = channel(img, "id");
    long shadowed = 0;
    for (size_t i = 0; i < v.size(); ++i) {
        EXPECT_GE(z[i], 0.0f);
        EXPECT_LE(z[i], 1.0f);
        if (id[i] != 0.0f || v[i] >= 0.99f) continue;
        ++shadowed;
        // Floor under the square: the blocker is the square (nearer than the floor), and the
        // final kernel is its penumbra, D (d - z) / (d z) = 1 * 1.5 / (3 * 1.5) = 1/3 in
        // tangent units: about 320 texels of the 512 map, which spans the square (0.53).
        EXPECT_GT(z[i], 0.0f);
        EXPECT_GT(w[i], 50.0f);
    }
    EXPECT_GT(shadowed, 500);
}

TEST(CssGL, LightAcrossTheReceiverPlaneKeepsItsPartAbove) {
    // A light low over the floor, tilted so that its rectangle crosses the floor's plane
    // (y = 0) diagonally: where no blocker is found, css's visibility on a floor that casts is
    // the share of the light above the receiver's tangent plane (visibility.frag aboveHorizon,
    // in closed form), and 1 on a floor that only receives: it does not hide the light from
    // itself, as `exact` finds (regression: the receiver ramp of conformance's tilted_receiver
    // was black on its sides, shadow-region MAE 0.231 against exact, now 0.046).
    // Expected: that share from 2000 x 2000 midpoint samples of the rectangle (error about
    // 1e-3 where the line crosses the samples).
    penumbra::scene::RectLight light;
    light.position = {2.5f, 0.15f, 0.2f};
    light.target = {0.0f, 0.0f, 0.0f};
    light.up = {0.4f, 1.0f, 0.5f};
    light.size = {1.4f, 1.0f};
    const glm::vec3 c = light.position, r = light.right(), u = light.upAxis();
    long above = 0;
    const int n = 2000;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const float x = (static_cast<float>(i) + 0.5f) / n - 0.5f;
            const float y = (static_cast<float>(j) + 0.5f) / n - 0.5f;
            above += (c + x * light.size.x * r + y * light.size.y * u).y > 0.0f;
        }
    const double share = static_cast<double>(above) / (double(n) * n);
    ASSERT_GT(share, 0.2);
    ASSERT_LT(share, 0.8);
    for (const char* role : {"both", "receiver"}) {
        auto img = renderScene("closed_form.json",
                               {{"technique", css()},
                                {"lights.0.position", "[2.5, 0.15, 0.2]"},
                                {"lights.0.up", "[0.4, 1.0, 0.5]"},
                                {"lights.0.size", "[1.4, 1.0]"},
                                {"objects.0.shadow", std::string("\"") + role + "\""}});
        const double expected = std::string(role) == "both" ? share : 1.0;
        const auto& v = channel(img, "visibility");
        const auto& z = channel(img, "css.z_avg");
        const auto& id = channel(img, "id");
        const auto& px = channel(img, "P.X");
        long checked = 0;
        double worst = 0;
        for (size_t i = 0; i < v.size(); ++i) {
            // Floor in front of the light (x < 2.2) with no blocker found (z_avg 0).
            if (id[i] != 0.0f || px[i] > 2.2f || z[i] != 0.0f) continue;
            worst = std::max(worst, std::fabs(v[i] - expected));
            ++checked;
        }
        std::printf(
            "css, light across the %s floor's plane: expected %.4f, worst |V - expected| %.4f "
            "over %ld pixels\n",
            role, expected, worst, checked);
        EXPECT_GT(checked, 5000);
        EXPECT_LT(worst, 3e-3);
    }
}

TEST(CssGL, ConvexObjectIsNotItsOwnBlocker) {
    // lone_sphere.json: a sphere (object 1, role both) under a 4 m light, nothing above it. A
    // convex object hides from itself only the light below its tangent plane (the horizon
    // share), so its upper half is lit as far as that share goes. Its own surface lies in the
    // map next to every one of its pixels, nearer the light than the pixel wherever the
    // kernel reaches up the curve: counted as a blocker, it darkened a band across the upper
    // half, and contact sharpening (the blocker at the receiver's own depth) turned it black
    // (regression: spheres_three_sizes' receivers 0.100 against exact at 320 x 240, 0.052 with
    // the exclusion). The test depth under each kernel is lowered by the drop of the
    // receiver's tangent plane over `self_exclude` of the kernel's half-width.
    const Image& ref = truth("lone_sphere.json");
    auto img = renderScene("lone_sphere.json", {{"technique", css()}});
    auto off = renderScene("lone_sphere.json", {{"technique", css(R"(, "self_exclude": 0)")}});
    const double on_mae = penumbra::testing::objectShadowMae(ref, img, 1);
    const double off_mae = penumbra::testing::objectShadowMae(ref, off, 1);
    std::printf("css, lone sphere's own surface: MAE %.4f (self_exclude 0: %.4f) vs exact\n",
                on_mae, off_mae);
    // Measured 0.0048 (0.007 before the own object's depth bounded the drop), and 0.128 with
    // self_exclude 0 (the old behaviour).
    EXPECT_LE(on_mae, 0.02);
    EXPECT_GT(off_mae, on_mae + 0.05);
}

TEST(CssGL, AFaceNearlyEdgeOnToTheLightKeepsTheBlockerItTouches) {
    // css_touching_face.json (random scene 30 of scripts/random-scenes, which nobody tuned
    // on): a box (object 3) tilted toward a 1 m light, one face against a sphere. Near the
    // sphere the face is nearly edge-on to the light, so its tangent plane, seen edge-on
    // inside the wide search kernel, dropped the test depth to 0: the sphere no longer counted
    // as a blocker and the face came out lit (0.90 where `exact` has 0). The drop now stops at
    // the nearest depth of the receiver's own object less the ring shift: its own surface
    // cannot come nearer, and blockers nearer than that count. Those within the ring shift of
    // it, at the very contact, still do not (the smooth test's ambiguity).
    // The paper's blocker depth: the middle one (the default) moves the box's blockers deeper
    // as well (measured 24 pixels and 0.195 with it), which is not what this checks.
    const Image& ref = truth("css_touching_face.json");
    auto img = renderScene("css_touching_face.json",
                           {{"technique", css(R"(, "blocker_depth": "nearest")")}});
    const auto& id = channel(ref, "id");
    const auto& vr = channel(ref, "visibility");
    const auto& v = channel(img, "visibility");
    long over_half = 0;
    for (size_t i = 0; i < v.size(); ++i)
        over_half += id[i] == 3.0f && std::fabs(v[i] - vr[i]) > 0.5f;
    const double mae = penumbra::testing::objectShadowMae(ref, img, 3, 100);
    std::printf("css, face touching a sphere: %ld pixels off by more than 0.5, MAE %.4f vs exact\n",
                over_half, mae);
    // Measured 7 and 0.126 (21 and 0.170 before), of 183 pixels.
    EXPECT_LE(over_half, 12);
    EXPECT_LE(mae, 0.145);
}
