// Image comparison: metrics on small images worked out by hand, every verdict branch of the idiff
// rule, channel and size mismatches, NaN handling, the difference image and the JSON keys.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "renderer/output/compare.h"

namespace penumbra::output {
namespace {

Image makeImage(int width, int height,
                const std::vector<std::pair<std::string, std::vector<float>>>& channels) {
    Image image;
    image.width = width;
    image.height = height;
    for (const auto& [name, pixels] : channels)
        image.channels.push_back({name, PixelType::Float, pixels});
    return image;
}

// 2x2, channels R and G. Differences (pixel order 0..3 = (0,0) (1,0) (0,1) (1,1)):
//   R: 0.1  0    0    0.3
//   G: 0    0.2  0    0
// 8 samples, sum 0.6 -> MAE 0.075; squares 0.14 -> RMSE sqrt(0.0175); max 0.3 at (1,1) R.
// Pixels over 0.15: 1 and 3 (2 of 4); over 0.05: 0, 1 and 3 (3 of 4).
struct SmallPair {
    Image ref = makeImage(2, 2, {{"R", {0.5f, 0.5f, 0.5f, 0.5f}}, {"G", {0, 0, 0, 0}}});
    Image test = makeImage(2, 2, {{"R", {0.6f, 0.5f, 0.5f, 0.8f}}, {"G", {0, 0.2f, 0, 0}}});
};

CompareOptions thresholds(double fail, double failPercent, double warn, double warnPercent) {
    CompareOptions o;
    o.fail = fail;
    o.fail_percent = failPercent;
    o.warn = warn;
    o.warn_percent = warnPercent;
    return o;
}

constexpr double kTol = 1e-6;  // the inputs are floats; the hand-computed values are exact

TEST(Compare, IdsRestrictEveryMetricToTheListedObjects) {
    // SmallPair with object ids 0 1 / 2 1: --ids 1 keeps pixels 1 and 3 (R 0 and 0.3, G 0.2
    // and 0): MAE 0.5 / 4, max 0.3 at (1,1); both pixels fail at 0.15, so the fraction is 1.
    SmallPair p;
    p.ref.channels.push_back({"id", PixelType::Float, {0, 1, 2, 1}});
    CompareOptions o = thresholds(0.15, 0, 0.05, 0);
    o.channels = {"R", "G"};
    o.ids = {1};
    const CompareResult r = compareImages(p.ref, p.test, o);
    EXPECT_EQ(r.pixels, 2);
    EXPECT_NEAR(r.mae, 0.125, kTol);
    EXPECT_NEAR(r.max, 0.3, kTol);
    EXPECT_EQ(r.fail_pixels, 2);
    EXPECT_DOUBLE_EQ(r.fail_fraction, 1.0);
    o.ids = {0, 2};  // pixels 0 and 2: only R's 0.1 differs
    const CompareResult other = compareImages(p.ref, p.test, o);
    EXPECT_EQ(other.pixels, 2);
    EXPECT_NEAR(other.mae, 0.025, kTol);
    const Image diff = differenceImage(p.ref, p.test, o);
    EXPECT_FLOAT_EQ(diff.channels[0].pixels[3], 0.0f);  // pixel 3 is object 1: left out
    EXPECT_NEAR(diff.channels[0].pixels[0], 0.1f, kTol);
}

TEST(Compare, IdsWithoutAnIdChannelAreAMismatch) {
    SmallPair p;
    CompareOptions o;
    o.ids = {0};
    try {
        compareImages(p.ref, p.test, o);
        FAIL() << "expected CompareMismatch";
    } catch (const CompareMismatch& e) {
        EXPECT_EQ(e.side(), CompareMismatch::Side::Reference);
        EXPECT_NE(std::string(e.what()).find("'id'"), std::string::npos);
    }
}

TEST(Compare, MetricsMatchHandComputedValues) {
    SmallPair p;
    const CompareResult r = compareImages(p.ref, p.test, thresholds(0.15, 0, 0.05, 0));
    EXPECT_EQ(r.width, 2);
    EXPECT_EQ(r.height, 2);
    EXPECT_EQ(r.channels, (std::vector<std::string>{"R", "G"}));
    EXPECT_NEAR(r.mae, 0.075, kTol);
    EXPECT_NEAR(r.rmse, std::sqrt(0.0175), kTol);
    EXPECT_NEAR(r.max, 0.3, kTol);
    EXPECT_EQ(r.max_x, 1);
    EXPECT_EQ(r.max_y, 1);
    EXPECT_EQ(r.max_channel, "R");
    EXPECT_NEAR(r.p99, 0.3, kTol);  // 8 samples: rank ceil(7.92) = 8, the largest
    EXPECT_EQ(r.nonfinite, 0);
    EXPECT_EQ(r.fail_pixels, 2);
    EXPECT_DOUBLE_EQ(r.fail_fraction, 0.5);
    EXPECT_EQ(r.warn_pixels, 3);
    EXPECT_DOUBLE_EQ(r.warn_fraction, 0.75);
    EXPECT_FALSE(r.shadow_mae);
    EXPECT_FALSE(r.shadow_pixels);

    ASSERT_EQ(r.per_channel.size(), 2u);
    const ChannelMetrics& red = r.per_channel[0];
    EXPECT_EQ(red.name, "R");
    EXPECT_NEAR(red.mae, 0.1, kTol);                // (0.1 + 0.3) / 4
    EXPECT_NEAR(red.rmse, std::sqrt(0.025), kTol);  // (0.01 + 0.09) / 4
    EXPECT_NEAR(red.max, 0.3, kTol);
    EXPECT_EQ(red.max_x, 1);
    EXPECT_EQ(red.max_y, 1);
    const ChannelMetrics& green = r.per_channel[1];
    EXPECT_NEAR(green.mae, 0.05, kTol);
    EXPECT_NEAR(green.rmse, 0.1, kTol);  // sqrt(0.04 / 4)
    EXPECT_NEAR(green.max, 0.2, kTol);
    EXPECT_EQ(green.max_x, 1);
    EXPECT_EQ(green.max_y, 0);
    EXPECT_NEAR(green.p99, 0.2, kTol);
}

TEST(Compare, P99IsTheNearestRankPercentile) {
    // 10x10, one channel, differences 0.00, 0.01, ..., 0.99 in shuffled order: the 99th of 100
    // sorted values is 0.98.
    Image ref = makeImage(10, 10, {{"Z", std::vector<float>(100, 0.0f)}});
    Image test = ref;
    for (int i = 0; i < 100; ++i)
        test.channels[0].pixels[static_cast<size_t>((i * 37) % 100)] =
            0.01f * static_cast<float>(i);
    const CompareResult r = compareImages(ref, test, {});
    EXPECT_NEAR(r.p99, 0.98, kTol);
    EXPECT_NEAR(r.per_channel[0].p99, 0.98, kTol);
    EXPECT_NEAR(r.mae, 0.495, kTol);
    EXPECT_NEAR(r.max, 0.99, kTol);
    EXPECT_EQ(r.max_x, (99 * 37) % 100 % 10);
    EXPECT_EQ(r.max_y, (99 * 37) % 100 / 10);

    // 1000 samples: rank 990 -> the 990th smallest.
    Image big = makeImage(1000, 1, {{"Z", std::vector<float>(1000, 0.0f)}});
    Image bigTest = big;
    for (int i = 0; i < 1000; ++i)
        bigTest.channels[0].pixels[static_cast<size_t>(i)] = static_cast<float>(i);
    EXPECT_DOUBLE_EQ(compareImages(big, bigTest, {}).p99, 989.0);
}

TEST(Compare, IdenticalImagesPassWithDefaults) {
    SmallPair p;
    const CompareResult r = compareImages(p.ref, p.ref, {});
    EXPECT_EQ(r.verdict, Verdict::Pass);
    EXPECT_EQ(r.mae, 0.0);
    EXPECT_EQ(r.max, 0.0);
    EXPECT_EQ(r.fail_pixels, 0);
    EXPECT_EQ(r.max_channel, "R");
}

TEST(Compare, DefaultsFailOnAnyDifference) {
    SmallPair p;
    EXPECT_EQ(compareImages(p.ref, p.test, {}).verdict, Verdict::Fail);
}

TEST(Compare, PassWhenEverythingIsUnderBothThresholds) {
    SmallPair p;
    EXPECT_EQ(compareImages(p.ref, p.test, thresholds(0.5, 0, 0.31, 0)).verdict, Verdict::Pass);
}

TEST(Compare, WarnWhenTooManyPixelsOverTheWarnThreshold) {
    SmallPair p;
    // 3 of 4 pixels over 0.05: more than 50 % warns, exactly 75 % is allowed.
    EXPECT_EQ(compareImages(p.ref, p.test, thresholds(0.5, 0, 0.05, 50)).verdict, Verdict::Warn);
    EXPECT_EQ(compareImages(p.ref, p.test, thresholds(0.5, 0, 0.05, 75)).verdict, Verdict::Pass);
}

TEST(Compare, FailWhenTooManyPixelsOverTheFailThreshold) {
    SmallPair p;
    // 2 of 4 pixels over 0.15: 25 % allowed fails; 50 % allowed falls through to the warn rule.
    EXPECT_EQ(compareImages(p.ref, p.test, thresholds(0.15, 25, 0.05, 100)).verdict, Verdict::Fail);
    EXPECT_EQ(compareImages(p.ref, p.test, thresholds(0.15, 50, 0.05, 0)).verdict, Verdict::Warn);
    EXPECT_EQ(compareImages(p.ref, p.test, thresholds(0.15, 50, 0.05, 100)).verdict, Verdict::Pass);
}

TEST(Compare, HardFailOverridesThePercentages) {
    SmallPair p;
    CompareOptions o = thresholds(0.15, 100, 0.05, 100);
    o.hard_fail = 0.25;  // max is 0.3
    EXPECT_EQ(compareImages(p.ref, p.test, o).verdict, Verdict::Fail);
    o.hard_fail = 0.35;
    EXPECT_EQ(compareImages(p.ref, p.test, o).verdict, Verdict::Pass);
}

TEST(Compare, ChannelsOptionRestrictsTheComparison) {
    SmallPair p;
    CompareOptions o = thresholds(0.15, 0, 0.15, 0);
    o.channels = {"G"};
    const CompareResult r = compareImages(p.ref, p.test, o);
    EXPECT_EQ(r.channels, std::vector<std::string>{"G"});
    EXPECT_NEAR(r.mae, 0.05, kTol);
    EXPECT_EQ(r.max_channel, "G");
    EXPECT_EQ(r.fail_pixels, 1);
    EXPECT_EQ(r.verdict, Verdict::Fail);
}

TEST(Compare, TestMayHaveExtraChannels) {
    SmallPair p;
    p.test.channels.push_back({"Z", PixelType::Float, {1, 2, 3, 4}});
    EXPECT_EQ(compareImages(p.ref, p.test, thresholds(1, 0, 1, 0)).channels.size(), 2u);
}

void expectMismatch(const Image& ref, const Image& test, const CompareOptions& o,
                    CompareMismatch::Side side, const std::string& words) {
    try {
        compareImages(ref, test, o);
        ADD_FAILURE() << "no exception";
    } catch (const CompareMismatch& e) {
        EXPECT_EQ(e.side(), side);
        EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
    EXPECT_THROW(differenceImage(ref, test, o), CompareMismatch);
}

TEST(Compare, MissingChannelsAreMismatches) {
    SmallPair p;
    using Side = CompareMismatch::Side;
    CompareOptions o;
    o.channels = {"R", "visibility"};
    expectMismatch(p.ref, p.test, o, Side::Reference, "reference has no channel 'visibility'");
    p.ref.channels.push_back({"visibility", PixelType::Float, {1, 1, 1, 1}});
    expectMismatch(p.ref, p.test, o, Side::Test, "test image has no channel 'visibility'");
    // Without --channels every reference channel must be in the test image.
    expectMismatch(p.ref, p.test, {}, Side::Test, "'visibility'");
}

TEST(Compare, DifferentSizesAreMismatches) {
    Image a = makeImage(2, 2, {{"R", {0, 0, 0, 0}}});
    Image b = makeImage(4, 1, {{"R", {0, 0, 0, 0}}});
    expectMismatch(a, b, {}, CompareMismatch::Side::Both, "2x2");
    expectMismatch(a, b, {}, CompareMismatch::Side::Both, "4x1");
}

TEST(Compare, ShadowRegionMae) {
    // Shadow pixels: 1 (0.5 vs 0.6, diff 0.1) and 2 (1 vs 0.998, diff 0.002); pixel 3 is lit in
    // both (0.9995 and 1 are not below 0.999). MAE = 0.102 / 2.
    SmallPair p;
    p.ref.channels.push_back({"visibility", PixelType::Float, {1, 0.5f, 1, 0.9995f}});
    p.test.channels.push_back({"visibility", PixelType::Float, {1, 0.6f, 0.998f, 1}});
    CompareOptions o;
    o.channels = {"R"};  // the shadow metric does not depend on the compared channels
    const CompareResult r = compareImages(p.ref, p.test, o);
    ASSERT_TRUE(r.shadow_mae);
    ASSERT_TRUE(r.shadow_pixels);
    EXPECT_EQ(*r.shadow_pixels, 2);
    EXPECT_NEAR(*r.shadow_mae, 0.051, kTol);
}

TEST(Compare, ShadowRegionMaeAbsentWithoutShadowOrChannel) {
    SmallPair p;
    p.ref.channels.push_back({"visibility", PixelType::Float, {1, 1, 1, 1}});
    CompareOptions o;
    o.channels = {"R"};
    CompareResult r = compareImages(p.ref, p.test, o);
    EXPECT_FALSE(r.shadow_pixels);  // the test image has no visibility
    EXPECT_FALSE(r.shadow_mae);
    p.test.channels.push_back({"visibility", PixelType::Float, {1, 1, 0.9991f, 1}});
    r = compareImages(p.ref, p.test, o);
    ASSERT_TRUE(r.shadow_pixels);
    EXPECT_EQ(*r.shadow_pixels, 0);
    EXPECT_FALSE(r.shadow_mae);
    EXPECT_TRUE(r.toJson()["shadow_mae"].is_null());
    EXPECT_EQ(r.toJson()["shadow_pixels"], 0);
}

TEST(Compare, NanAndInfCountAsInfiniteDifferences) {
    SmallPair p;
    p.test.channels[1].pixels[2] = std::numeric_limits<float>::quiet_NaN();  // G at (0,1)
    CompareOptions loose = thresholds(1e9, 0, 1e9, 0);
    CompareResult r = compareImages(p.ref, p.test, loose);
    EXPECT_EQ(r.verdict, Verdict::Fail);
    EXPECT_EQ(r.fail_pixels, 1);
    EXPECT_EQ(r.nonfinite, 1);
    EXPECT_TRUE(std::isinf(r.max));
    EXPECT_EQ(r.max_x, 0);
    EXPECT_EQ(r.max_y, 1);
    EXPECT_EQ(r.max_channel, "G");
    EXPECT_NEAR(r.mae, 0.6 / 7, kTol);  // mean of the 7 finite differences
    EXPECT_TRUE(r.toJson()["max"].is_null());
    EXPECT_EQ(r.toJson()["nonfinite"], 1);

    // Even 100 % allowed failing pixels does not save it from --hardfail.
    CompareOptions hard = thresholds(1e9, 100, 1e9, 100);
    hard.hard_fail = 1e9;
    EXPECT_EQ(compareImages(p.ref, p.test, hard).verdict, Verdict::Fail);

    // NaN in both images still fails; so does inf against a finite value or -inf.
    Image a = makeImage(1, 1, {{"R", {std::numeric_limits<float>::quiet_NaN()}}});
    EXPECT_EQ(compareImages(a, a, loose).verdict, Verdict::Fail);
    Image b = makeImage(1, 1, {{"R", {std::numeric_limits<float>::infinity()}}});
    Image c = makeImage(1, 1, {{"R", {-std::numeric_limits<float>::infinity()}}});
    Image d = makeImage(1, 1, {{"R", {1.0f}}});
    EXPECT_EQ(compareImages(b, c, loose).verdict, Verdict::Fail);
    EXPECT_EQ(compareImages(b, d, loose).verdict, Verdict::Fail);
}

TEST(Compare, EqualInfinitiesAreEqual) {
    // Z is +inf on the background: the same background in both images must pass exactly.
    const float inf = std::numeric_limits<float>::infinity();
    Image a = makeImage(2, 1, {{"Z", {inf, 2.0f}}});
    Image b = makeImage(2, 1, {{"Z", {inf, 2.0f}}});
    const CompareResult r = compareImages(a, b, {});
    EXPECT_EQ(r.verdict, Verdict::Pass);
    EXPECT_EQ(r.nonfinite, 0);
    EXPECT_EQ(r.max, 0.0);
    EXPECT_EQ(differenceImage(a, b, {}).channels[0].pixels[0], 0.0f);
}

TEST(Compare, IdsThatSelectNoPixelAreAnError) {
    Image a = makeImage(2, 1, {{"R", {0, 0}}, {"id", {0, -1}}});
    CompareOptions o;
    o.ids = {3, 4};
    try {
        (void)compareImages(a, a, o);
        FAIL() << "expected CompareMismatch";
    } catch (const CompareMismatch& e) {
        EXPECT_EQ(e.side(), CompareMismatch::Side::Reference);
        EXPECT_NE(std::string(e.what()).find("--ids 3,4 selects no pixel"), std::string::npos)
            << e.what();
    }
    o.ids = {0};
    EXPECT_EQ(compareImages(a, a, o).pixels, 1);
}

TEST(Compare, DifferenceImageHoldsAbsoluteDifferences) {
    SmallPair p;
    p.test.channels[0].pixels[1] = std::numeric_limits<float>::quiet_NaN();
    p.test.channels[1].pixels[0] = -0.25f;
    const Image d = differenceImage(p.ref, p.test, {});
    EXPECT_EQ(d.width, 2);
    EXPECT_EQ(d.height, 2);
    ASSERT_EQ(d.channels.size(), 2u);
    EXPECT_EQ(d.channels[0].name, "R");
    EXPECT_EQ(d.channels[0].type, PixelType::Float);
    EXPECT_NEAR(d.channels[0].pixels[0], 0.1f, kTol);
    EXPECT_TRUE(std::isinf(d.channels[0].pixels[1]));
    EXPECT_NEAR(d.channels[0].pixels[3], 0.3f, kTol);
    EXPECT_NEAR(d.channels[1].pixels[0], 0.25f, kTol);
    EXPECT_NEAR(d.channels[1].pixels[1], 0.2f, kTol);
}

TEST(Compare, JsonHasSnakeCaseKeysAndVerdictWords) {
    SmallPair p;
    p.ref.channels.push_back({"visibility", PixelType::Float, {1, 0.5f, 1, 1}});
    p.test.channels.push_back({"visibility", PixelType::Float, {1, 0.5f, 1, 1}});
    CompareOptions o = thresholds(0.15, 0, 0.05, 0);
    o.hard_fail = 2.0;
    const nlohmann::json j = compareImages(p.ref, p.test, o).toJson();
    for (const char* key :
         {"verdict",       "width",      "height",        "channels",      "mae",
          "rmse",          "max",        "max_x",         "max_y",         "max_channel",
          "p99",           "nonfinite",  "fail_pixels",   "fail_fraction", "warn_pixels",
          "warn_fraction", "shadow_mae", "shadow_pixels", "thresholds",    "per_channel"})
        EXPECT_TRUE(j.contains(key)) << key;
    EXPECT_EQ(j["verdict"], "fail");
    EXPECT_EQ(j["fail_pixels"], 2);
    EXPECT_EQ(j["shadow_pixels"], 1);
    EXPECT_EQ(j["shadow_mae"], 0.0);
    EXPECT_EQ(j["thresholds"]["hard_fail"], 2.0);
    EXPECT_EQ(j["thresholds"]["fail_percent"], 0.0);
    EXPECT_EQ(j["per_channel"].size(), 3u);
    EXPECT_EQ(j["per_channel"][0]["name"], "R");
    EXPECT_TRUE(j["per_channel"][0].contains("p99"));

    EXPECT_EQ(compareImages(p.ref, p.ref, {}).toJson()["verdict"], "pass");
    EXPECT_EQ(compareImages(p.ref, p.test, thresholds(1, 0, 0.05, 0)).toJson()["verdict"], "warn");
    EXPECT_TRUE(compareImages(p.ref, p.ref, {}).toJson()["thresholds"]["hard_fail"].is_null());
}

}  // namespace
}  // namespace penumbra::output
