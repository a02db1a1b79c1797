// The light-centred windows and sample frusta are fitted to each caster's box, not to their
// union: checked without a context on a tilted light whose casters' union reaches behind it.
#include <gtest/gtest.h>

#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "renderer/passes/light_windows.h"
#include "renderer/passes/shadow_maps.h"

using namespace penumbra;
using passes::Bounds;

namespace {

Bounds box(glm::vec3 lo, glm::vec3 hi) {
    Bounds b;
    b.extend(lo), b.extend(hi);
    return b;
}

// A light at (0, 3, 0) looking down at 45 degrees along (1, -1, 0): a point's depth in front of
// it is (x - y + 3) / sqrt(2).
scene::RectLight tiltedLight() {
    scene::RectLight l;
    l.position = {0, 3, 0};
    l.target = {3, 0, 0};
    l.up = {0, 0, -1};
    l.size = {0.5f, 0.5f};
    return l;
}

// Two casters in front of the light (nearest corners at depth 1.8 / sqrt(2) and 2.3 / sqrt(2))
// whose union's corner (-1, 2.7, z) lies 0.7 / sqrt(2) behind the light's plane (rand64's case).
std::vector<passes::WorldBox> casters() {
    return {box({-1.0f, 0.0f, -0.1f}, {-0.8f, 0.2f, 0.1f}),
            box({2.0f, 2.5f, -0.1f}, {2.2f, 2.7f, 0.1f})};
}

float depth(glm::vec3 p) {
    return (p.x - p.y + 3.0f) / std::sqrt(2.0f);
}

}  // namespace

TEST(LightWindows, FitTheCastersBoxesNotTheirUnionThatReachesBehindTheLight) {
    const auto light = tiltedLight();
    const auto boxes = casters();
    Bounds all;
    for (const auto& b : boxes)
        for (int i = 0; i < 8; ++i) all.extend(b.corner(i));
    ASSERT_LT(depth({-1.0f, 2.7f, 0.0f}), 0.0f);  // the scene this test is about

    const passes::LightWindow w = passes::windowOf(light, boxes);
    EXPECT_NEAR(w.near, depth({-1.0f, 0.2f, 0.0f}), 1e-4f);
    EXPECT_NEAR(w.far, depth({2.2f, 2.5f, 0.0f}), 1e-3f);
    // Seen from the light's centre, the corners' tangents along right() span -3.8 / 1.8 (the
    // corner (-1, 0.2)) to 1.9 / 2.5 (the corner (2.2, 2.7)); the union's window, even cut to
    // the widest view, reaches 20 times nearer and spans that view.
    EXPECT_NEAR(w.lo.x, -3.8f / 1.8f, 1e-4f);
    EXPECT_NEAR(w.lo.x + w.size.x, 1.9f / 2.5f, 1e-4f);
    const passes::WorldBox union_only[] = {all};
    const passes::LightWindow u = passes::windowOf(light, union_only);
    EXPECT_LT(u.near, 0.05f * w.near);
    EXPECT_GT(u.size.x, passes::kMaxViewTan);

    // A sample frustum from a corner of the light sees the casters from no nearer than they are.
    const glm::vec3 corner = light.corners()[0];
    const passes::SampleView v = passes::makeSampleView(light, corner, boxes, 1.0f, 256);
    EXPECT_GT(v.forward.w, 0.95f * (depth({-1.0f, 0.2f, 0.0f}) - 0.1f));
    EXPECT_LT(1.0f / v.frustum.z, 3.2f);  // width of the window (tangent units)
}

TEST(LightWindows, ABoxWhollyBehindTheLightIsLeftOut) {
    const auto light = tiltedLight();
    auto boxes = casters();
    const passes::LightWindow w = passes::windowOf(light, boxes);
    boxes.push_back(box({-3.0f, 4.0f, -0.1f}, {-2.8f, 4.2f, 0.1f}));  // depth < 0 at every corner
    const passes::LightWindow with = passes::windowOf(light, boxes);
    EXPECT_EQ(with.near, w.near);
    EXPECT_EQ(with.far, w.far);
    EXPECT_EQ(with.lo, w.lo);
    EXPECT_EQ(with.size, w.size);
    EXPECT_TRUE(passes::windowOf(light, std::span(boxes).last(1)).empty());
}

TEST(LightWindows, ACasterAcrossTheLightsPlaneSetsNearWhereTheWidestViewMeetsIt) {
    // A light at (0, 3, 0) looking straight down: its frame is x = world x, z = 3 - world y.
    // One caster crosses the light's plane 1.9-2.1 m beside it (z from -0.5 to 0.5); a view
    // holds at most 80 degrees from the axis (|x| <= 5.67 z), so the nearest of it any map
    // holds lies at z = 1.9 / 5.67. The whole box's nearest corner (behind the plane) set near
    // to far x 1e-4 before, so every window had the depth precision and blocker search of a
    // caster touching the light.
    scene::RectLight light;
    light.position = {0, 3, 0};
    light.target = {0, 0, 0};
    light.up = {0, 0, -1};
    const std::vector<passes::WorldBox> boxes = {box({1.9f, 2.5f, -0.1f}, {2.1f, 3.5f, 0.1f}),
                                                 box({-0.5f, 0.5f, -0.5f}, {0.5f, 0.6f, 0.5f})};
    const passes::LightWindow w = passes::windowOf(light, boxes);
    EXPECT_NEAR(w.near, 1.9f / passes::kMaxViewTan, 1e-4f);
    EXPECT_NEAR(w.far, 2.5f, 1e-3f);
    EXPECT_NEAR(w.lo.x + w.size.x, passes::kMaxViewTan, 1e-3f);
    const passes::SampleView v = passes::makeSampleView(light, light.position, boxes, 1.0f, 256);
    EXPECT_NEAR(v.forward.w, 1.9f / passes::kMaxViewTan - 0.01f * 2.5f, 0.01f);
    // The cut keeps what a view holds: every vertex lies within the widest view.
    for (const glm::vec3& p : passes::visibleVertices(boxes, light, light.position))
        EXPECT_LE(std::max(std::fabs(p.x), std::fabs(p.y)), passes::kMaxViewTan * p.z + 1e-4f);
}

TEST(LightWindows, AnOccluderMapsTexelsTakeTheLightsAspectUpToTwoToOne) {
    // A light at (0, 3, 0) looking straight down over one 1 m cube: its casters' window is
    // square. The occluder window grows it to the light's aspect, so that a square map's texels
    // have it, but at most 2:1: at 100:1 (a 1.5 x 0.015 tube) the cube filled a hundredth of
    // the map's width and its shadows came out 0.28 off `exact` (tests/data/gl/strip_light.json).
    scene::RectLight light;
    light.position = {0, 3, 0};
    light.target = {0, 0, 0};
    light.up = {0, 0, -1};
    const std::vector<passes::WorldBox> boxes = {box({-0.5f, 0.0f, -0.5f}, {0.5f, 1.0f, 0.5f})};
    const passes::LightWindow own = passes::windowOf(light, boxes);
    ASSERT_NEAR(own.size.x, own.size.y, 1e-5f);
    const auto aspect = [&](glm::vec2 size) {
        light.size = size;
        const passes::LightWindow w = passes::occluderWindow(light, boxes);
        EXPECT_GE(w.size.x, own.size.x - 1e-5f);  // it holds the casters' window
        EXPECT_GE(w.size.y, own.size.y - 1e-5f);
        EXPECT_EQ(w.near, own.near);
        return w.size.x / w.size.y;
    };
    EXPECT_NEAR(aspect({0.5f, 0.5f}), 1.0f, 1e-5f);
    EXPECT_NEAR(aspect({1.5f, 1.0f}), 1.5f, 1e-5f);
    EXPECT_NEAR(aspect({1.0f, 1.5f}), 1.0f / 1.5f, 1e-5f);
    EXPECT_NEAR(aspect({1.5f, 0.015f}), passes::kMaxTexelAspect, 1e-5f);
    EXPECT_NEAR(aspect({0.001f, 1.5f}), 1.0f / passes::kMaxTexelAspect, 1e-5f);
}

TEST(LightWindows, ATurnedPlaneIsBoundedByItsOwnCornersNotTheirAxisAlignedBox) {
    // A 4 x 4 floor 3 m below a light looking straight at it, both turned 45 degrees about x
    // and then 45 about z (scripts/scale-scenes --rotate): the floor faces the light, every
    // point of it 3 m deep. Its turned box's corners are the floor's, so the window's near and
    // far are 3; the axis-aligned box around them reaches from behind the light to 6.4 m deep,
    // which set `css`'s depth range and each object's nearest depth there (every caster counted
    // as the floor's own surface: no shadow at all on caster_outside_view turned).
    glm::mat4 turn = glm::rotate(glm::mat4(1.0f), glm::radians(45.0f), glm::vec3(0, 0, 1));
    turn = glm::rotate(turn, glm::radians(45.0f), glm::vec3(1, 0, 0));
    const auto turned = [&](glm::vec3 p, float w) { return glm::vec3(turn * glm::vec4(p, w)); };
    scene::RectLight light;
    light.position = turned({0, 3, 0}, 1.0f);
    light.target = turned({0, 0, 0}, 1.0f);
    light.up = turned({0, 0, -1}, 0.0f);
    const Bounds floor = box({-2.0f, 0.0f, -2.0f}, {2.0f, 0.0f, 2.0f});
    const passes::WorldBox own[] = {passes::WorldBox(floor, turn)};
    Bounds aligned;
    for (int i = 0; i < 8; ++i) {
        EXPECT_EQ(own[0].corner(i), turned(floor.corner(i), 1.0f));
        aligned.extend(own[0].corner(i));
    }
    const passes::LightWindow w = passes::windowOf(light, own);
    EXPECT_NEAR(w.near, 3.0f, 1e-4f);
    EXPECT_NEAR(w.far, 3.0f, 1e-3f);
    EXPECT_NEAR(w.lo.x, -2.0f / 3.0f, 1e-4f);
    EXPECT_NEAR(w.size.y, 4.0f / 3.0f, 1e-4f);
    const passes::WorldBox around[] = {aligned};
    const passes::LightWindow a = passes::windowOf(light, around);
    EXPECT_LT(a.near, 2.0f);
    EXPECT_GT(a.far - a.near, 2.0f);
}
