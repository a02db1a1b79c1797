// `bitmask` gap filling's neighbour depths (techniques/bitmask/neighbour_depths.h): every level
// holds each texel's distance with those below and above it, from the pyramid or, at levels 1
// and up, from the microrects' depths, and kNone past the map's edges.
#include <gtest/gtest.h>

#include <vector>

#include "gl_test_env.h"
#include "renderer/gl/program.h"
#include "renderer/techniques/bitmask/neighbour_depths.h"

using namespace penumbra;
using techniques::bitmask::NeighbourDepths;

namespace {

constexpr int kSize = 8, kLevels = 4;
constexpr float kNone = 3.0e38f;  // neighbours.comp's

// The distinct distance of texel (X, Y) of LEVEL in the pyramid (FROM_RECTS 0) or the
// microrects' depths (1).
float distance(int from_rects, int level, int x, int y) {
    return float(from_rects * 1000 + level * 100 + y * 10 + x);
}

// An RG32F pyramid (or, RECTS, an R32F mip chain) of kSize with distance() in every texel.
gl::Texture sourceTexture(bool rects) {
    gl::Texture t = gl::createTexture2D(rects ? GL_R32F : GL_RG32F, kSize, kSize,
                                        "neighbours test source", kLevels);
    for (int level = 0; level < kLevels; ++level) {
        const int n = kSize >> level;
        std::vector<float> texels;
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) {
                texels.push_back(distance(rects ? 1 : 0, level, x, y));
                if (!rects) texels.push_back(-1.0f);  // the max, which no read takes
            }
        glTextureSubImage2D(t.id(), level, 0, 0, n, n, rects ? GL_RED : GL_RG, GL_FLOAT,
                            texels.data());
    }
    return t;
}

void checkLevels(const NeighbourDepths& n, bool with_rects) {
    for (int level = 0; level < kLevels; ++level) {
        const int size = kSize >> level;
        std::vector<float> got(static_cast<size_t>(size * size * 4));
        glGetTextureImage(n.texture().id(), level, GL_RGBA, GL_FLOAT,
                          static_cast<GLsizei>(got.size() * 4), got.data());
        const int from = with_rects && level > 0 ? 1 : 0;
        for (int y = 0; y < size; ++y)
            for (int x = 0; x < size; ++x) {
                const float* t = &got[static_cast<size_t>((y * size + x) * 4)];
                SCOPED_TRACE("level " + std::to_string(level) + " texel " + std::to_string(x) +
                             ", " + std::to_string(y));
                EXPECT_EQ(t[0], distance(from, level, x, y));
                EXPECT_EQ(t[1], y > 0 ? distance(from, level, x, y - 1) : kNone);
                EXPECT_EQ(t[2], y < size - 1 ? distance(from, level, x, y + 1) : kNone);
            }
    }
}

}  // namespace

TEST(BitmaskNeighboursGL, EveryLevelHoldsItsTexelsWithThoseBelowAndAbove) {
    penumbra::testing::glInfo();
    const gl::Texture pyramid = sourceTexture(false);
    const gl::Texture rects = sourceTexture(true);
    NeighbourDepths n(kSize);
    n.build(pyramid, nullptr);
    checkLevels(n, false);
    n.build(pyramid, &rects);
    checkLevels(n, true);
}
