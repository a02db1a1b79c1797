// `bitmask` microrects (techniques/bitmask/microrects.h) built from a synthetic map: every
// level's extents cover the caster texels, and `rect_fit` coverage shrinks a rectangle to the
// area of the casters inside it, within the bounding rectangle of the paper's merge; each keeps
// its nearest and farthest caster texel.
#include <gtest/gtest.h>

#include <vector>

#include "gl_test_env.h"
#include "renderer/techniques/bitmask/depth_ranges.h"
#include "renderer/techniques/bitmask/microrects.h"

using namespace penumbra;
using techniques::bitmask::DepthRanges;
using techniques::bitmask::MicroRects;

namespace {

constexpr int kMapSide = 64;

// Whether texel (X, Y) holds a caster: a right triangle whose hypotenuse cuts every coarse
// block diagonally, and a full square away from it.
bool isCaster(int x, int y) {
    return x + y < 40 || (x >= 48 && x < 64 && y >= 48 && y < 64);
}

// An RG32F level-0 (min, max) map with isCaster() at distance 2 + x / 100, kEmpty elsewhere.
gl::Texture casterMap() {
    gl::Texture t = gl::createTexture2D(GL_RG32F, kMapSide, kMapSide, "microrects test map", 1);
    std::vector<float> texels;
    for (int y = 0; y < kMapSide; ++y)
        for (int x = 0; x < kMapSide; ++x) {
            const float z = isCaster(x, y) ? 2.0f + float(x) / 100.0f : DepthRanges::kEmpty;
            texels.insert(texels.end(), {z, z});
        }
    glTextureSubImage2D(t.id(), 0, 0, 0, kMapSide, kMapSide, GL_RG, GL_FLOAT, texels.data());
    return t;
}

std::vector<float> levelTexels(const gl::Texture& t, int k) {
    const int n = kMapSide >> k;
    std::vector<float> v(static_cast<size_t>(n * n * 4));
    glGetTextureImage(t.id(), k, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(v.size() * 4), v.data());
    return v;
}

}  // namespace

TEST(BitmaskMicroRectsGL, EveryLevelCoversTheCastersAndTheFitShrinksToThoseInside) {
    penumbra::testing::glInfo();
    const gl::Texture m = casterMap();
    MicroRects bounds(kMapSide, false, false), fitted(kMapSide, false, true);
    bounds.build(m);
    fitted.build(m);
    int shrunk = 0;
    for (int k = 1; (kMapSide >> k) >= 1; ++k) {
        SCOPED_TRACE("level " + std::to_string(k));
        const auto box = levelTexels(bounds.extent(), k), fit = levelTexels(fitted.extent(), k);
        // Every caster texel lies in some microrect (the map's top and right edges too).
        std::vector<bool> covered(kMapSide * kMapSide, false);
        for (size_t i = 0; i < box.size(); i += 4) {
            const float* b = &box[i];
            if (b[0] > b[2]) continue;
            for (int y = int(b[1]); y <= int(b[3]); ++y)
                for (int x = int(b[0]); x <= int(b[2]); ++x) covered[y * kMapSide + x] = true;
            // The fit lies inside the bounding rectangle, with the area of the casters there.
            const float* f = &fit[i];
            EXPECT_GE(f[0], b[0] - 1e-3);
            EXPECT_GE(f[1], b[1] - 1e-3);
            EXPECT_LE(f[2], b[2] + 1e-3);
            EXPECT_LE(f[3], b[3] + 1e-3);
            int inside = 0;
            for (int y = int(b[1]); y <= int(b[3]); ++y)
                for (int x = int(b[0]); x <= int(b[2]); ++x) inside += isCaster(x, y) ? 1 : 0;
            const double area = (b[2] + 1.0 - b[0]) * (b[3] + 1.0 - b[1]);
            if (inside == int(area)) {
                for (int c = 0; c < 4; ++c) EXPECT_EQ(f[c], b[c]);  // a full one stays
            } else {
                EXPECT_NEAR((f[2] + 1.0 - f[0]) * (f[3] + 1.0 - f[1]), inside, 1e-3 * inside);
                ++shrunk;
            }
        }
        for (int y = 0; y < kMapSide; ++y)
            for (int x = 0; x < kMapSide; ++x)
                if (isCaster(x, y)) {
                    EXPECT_TRUE(covered[y * kMapSide + x]) << x << ", " << y;
                }
    }
    EXPECT_GT(shrunk, 10);  // the hypotenuse's blocks
}

TEST(BitmaskMicroRectsGL, EachMicrorectKeepsItsNearestAndFarthestCasterTexel) {
    // `split` reads the farthest caster texel a microrect merged beside its nearest. The map's
    // distance grows with x alone, and the paper's bounding rectangle (`rect_fit` bounds) has a
    // merged texel in its first column and one in its last: its nearest is its first column's
    // distance and its farthest its last's, at every level.
    penumbra::testing::glInfo();
    const gl::Texture m = casterMap();
    MicroRects bounds(kMapSide, false, false);
    bounds.build(m);
    int spread = 0;
    for (int k = 1; (kMapSide >> k) >= 1; ++k) {
        SCOPED_TRACE("level " + std::to_string(k));
        const auto box = levelTexels(bounds.extent(), k), depth = levelTexels(bounds.depth(), k);
        for (size_t i = 0; i < box.size(); i += 4) {
            if (box[i] > box[i + 2]) {
                EXPECT_GE(depth[i], DepthRanges::kEmpty);  // no caster
                continue;
            }
            EXPECT_NEAR(depth[i], 2.0 + box[i] / 100.0, 1e-5);
            EXPECT_NEAR(depth[i + 1], 2.0 + box[i + 2] / 100.0, 1e-5);
            spread += depth[i + 1] > depth[i] ? 1 : 0;
        }
    }
    EXPECT_GT(spread, 10);
}
