// `adaptive`'s map side per light (max_texel) without GL: the windows of conformance scenes and
// a random one, and the rule's limits.
#include <gtest/gtest.h>

#include "renderer/techniques/adaptive/map_size.h"

namespace penumbra::techniques::adaptive {
namespace {

// The centre windows' widest sides (tangent units) measured on the scenes.
TEST(MapSide, FollowsTheCasterWindowsTexel) {
    EXPECT_EQ(mapSideFor(1024, 0.002, 0.40), 256);  // light_size_*: a sphere under the light
    EXPECT_EQ(mapSideFor(1024, 0.002, 0.67), 384);  // torus_like_ring: 335 texels
    EXPECT_EQ(mapSideFor(1024, 0.002, 1.43), 768);  // spheres_three_sizes: 715
    // Random scene 64 (tests/data/gl/tilted_light_union.json): a window at the 80-degree clamp.
    EXPECT_EQ(mapSideFor(1024, 0.002, 6.0), 1024);
    EXPECT_EQ(mapSideFor(4096, 0.002, 6.0), 3072);    // 3000 texels
    EXPECT_EQ(mapSideFor(4096, 0.002, 4.096), 2048);  // exactly 0.002 at 2048
    EXPECT_EQ(mapSideFor(4096, 0.002, 4.1), 2048 + 128);
}

TEST(MapSide, LimitsAndOffSwitch) {
    EXPECT_EQ(mapSideFor(1024, 0.0, 0.4), 1024);   // max_texel 0: map_size
    EXPECT_EQ(mapSideFor(128, 0.002, 0.01), 128);  // never above map_size
    EXPECT_EQ(mapSideFor(768, 0.002, 6.0), 768);   // a side that is no power of two
    EXPECT_EQ(mapSideFor(768, 0.002, 0.4), 256);
    EXPECT_EQ(mapSideFor(1000, 0.002, 1.99), 1000);  // map_size no multiple of the step
    EXPECT_EQ(mapSideFor(1024, 0.002, 1e30), 1024);  // a huge window: map_size
    EXPECT_EQ(mapSideFor(1024, 0.002, 0.0), 256);    // a degenerate window: the smallest
}

}  // namespace
}  // namespace penumbra::techniques::adaptive
