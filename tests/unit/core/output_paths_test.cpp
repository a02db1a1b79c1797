// Output patterns: # runs, several frames without #, extensions, negative frames.
#include <gtest/gtest.h>

#include "renderer/core/output_paths.h"

using penumbra::expandFramePattern;
using penumbra::replaceExtension;

TEST(OutputPaths, HashRunsBecomePaddedFrames) {
    EXPECT_EQ(expandFramePattern("shots/bunny.####.exr", 7, true), "shots/bunny.0007.exr");
    EXPECT_EQ(expandFramePattern("a.##.exr", 123, true), "a.123.exr");  // wider than the run
    EXPECT_EQ(expandFramePattern("f#/x#.exr", 3, false), "f3/x3.exr");
    EXPECT_EQ(expandFramePattern("n.###.exr", -4, true), "n.-004.exr");
}

TEST(OutputPaths, SeveralFramesWithoutHashGetNumbered) {
    EXPECT_EQ(expandFramePattern("out/x.exr", 12, true), "out/x.0012.exr");
    EXPECT_EQ(expandFramePattern("out.d/x", 1, true), "out.d/x.0001");
    EXPECT_EQ(expandFramePattern("out/x.exr", 12, false), "out/x.exr");
}

TEST(OutputPaths, ReplaceExtension) {
    EXPECT_EQ(replaceExtension("a/b.0001.exr", ".json"), "a/b.0001.json");
    EXPECT_EQ(replaceExtension("a.d/b", ".json"), "a.d/b.json");
    EXPECT_EQ(replaceExtension(".hidden", ".json"), ".hidden.json");
}
