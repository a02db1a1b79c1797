// `adaptive`'s map side per light (max_texel) without GL: the windows of conformance scenes and
// a random one, and the rule's limits.
#include <gtest/gtest.h>

#include "renderer/techniques/adaptive/map_size.h"

namespace penumbra::techniques::adaptive {
namespace {

// The centre windows' widest sides (tangent units) measured on the scenes.
TEST(MapSide, FollowsTheCasterWindowsTexel) {
    EXPECT_EQ(mapSideFor(1024, 0.002, 0.40), 256);   // light_size_*: a sphere under the light
    EXPECT_EQ(mapSideFor(1024, 0.002, 0.67), 512);   // torus_like_ring
    EXPECT_EQ(mapSideFor(1024, 0.002, 1.43), 1024);  // spheres_three_sizes
    // Random scene 64 (tests/data/gl/tilted_light_union.json): a window at the 80-degree clamp.
    EXPECT_EQ(mapSideFor(1024, 0.002, 6.0), 1024);
    EXPECT_EQ(mapSideFor(4096, 0.002, 6.0), 4096);
    EXPECT_EQ(mapSideFor(4096, 0.002, 4.0), 2048);  // exactly 0.002 at 2048
}

TEST(MapSide, LimitsAndOffSwitch) {
    EXPECT_EQ(mapSideFor(1024, 0.0, 0.4), 1024);   // max_texel 0: map_size
    EXPECT_EQ(mapSideFor(128, 0.002, 0.01), 128);  // never above map_size
    EXPECT_EQ(mapSideFor(768, 0.002, 6.0), 768);   // a side that is no power of two
    EXPECT_EQ(mapSideFor(768, 0.002, 0.4), 256);
    EXPECT_EQ(mapSideFor(1024, 0.002, 0.0), 256);  // a degenerate window: the smallest
}

}  // namespace
}  // namespace penumbra::techniques::adaptive
