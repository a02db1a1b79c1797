// `bitmask`'s acceleration structures against brute force on the CPU: every HSM level and
// every MSSM / YSM layer a query can reach holds the exact (min, max) of its texels.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "gl_test_env.h"
#include "renderer/gl/debug.h"
#include "renderer/techniques/bitmask/depth_ranges.h"

using namespace penumbra;
using techniques::bitmask::Accel;
using techniques::bitmask::DepthRanges;

namespace {

struct Range {
    float lo = 1e38f, hi = -1e38f;
};

// A random level-0 map of SIZE^2 distances, a fifth of them empty.
std::vector<float> randomMap(int size, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> dist(1.0f, 9.0f), u(0.0f, 1.0f);
    std::vector<float> rg(static_cast<size_t>(size * size * 2));
    for (size_t i = 0; i < rg.size(); i += 2)
        rg[i] = rg[i + 1] = u(rng) < 0.2f ? DepthRanges::kEmpty : dist(rng);
    return rg;
}

// The (min, max) over [x0, x0 + w) x [y0, y0 + w) of MAP, clipped to the map.
Range bruteRange(const std::vector<float>& map, int size, int x0, int y0, int w) {
    Range r;
    for (int y = y0; y < std::min(y0 + w, size); ++y)
        for (int x = x0; x < std::min(x0 + w, size); ++x) {
            r.lo = std::min(r.lo, map[size_t((y * size + x) * 2)]);
            r.hi = std::max(r.hi, map[size_t((y * size + x) * 2 + 1)]);
        }
    return r;
}

std::vector<float> readLevel(const gl::Texture& t, int level, int texels) {
    std::vector<float> out(static_cast<size_t>(texels * 2));
    glGetTextureImage(t.id(), level, GL_RG, GL_FLOAT, static_cast<GLsizei>(out.size() * 4),
                      out.data());
    return out;
}

// Builds ACCEL over a random MAP_SIZE map and checks the HSM and the MSSM layers from FIRST.
void checkStructures(Accel accel, int map_size, int ysm_size, int first_layer) {
    penumbra::testing::glInfo();
    DepthRanges ranges(map_size, accel, ysm_size);
    const auto map = randomMap(map_size, static_cast<unsigned>(map_size + ysm_size));
    glTextureSubImage2D(ranges.hsm().id(), 0, 0, 0, map_size, map_size, GL_RG, GL_FLOAT,
                        map.data());
    ranges.buildHsm();
    ranges.buildMssm();
    int wrong = 0;
    for (int level = 0; level < ranges.levels(); ++level) {
        const int n = map_size >> level, w = 1 << level;
        const auto got = readLevel(ranges.hsm(), level, n * n);
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) {
                const Range r = bruteRange(map, map_size, x * w, y * w, w);
                wrong += got[size_t((y * n + x) * 2)] != r.lo ||
                         got[size_t((y * n + x) * 2 + 1)] != r.hi;
            }
    }
    EXPECT_EQ(wrong, 0) << "HSM texels wrong";
    if (accel == Accel::Hsm) return;
    const int base = ranges.mssmBase(), n = map_size >> base, layers = ranges.mssmLayers();
    std::vector<float> all(static_cast<size_t>(n * n * layers * 2));
    glGetTextureImage(ranges.mssm().id(), 0, GL_RG, GL_FLOAT, static_cast<GLsizei>(all.size() * 4),
                      all.data());
    gl::checkErrors("depth ranges test");
    // The MSSM part's source is HSM level BASE: brute force over it.
    const auto source = readLevel(ranges.hsm(), base, n * n);
    for (int k = first_layer; k < layers; ++k) {
        int layer_wrong = 0;
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) {
                const Range r = bruteRange(source, n, x, y, 1 << k);
                const size_t i = size_t(((k * n + y) * n + x) * 2);
                layer_wrong += all[i] != r.lo || all[i + 1] != r.hi;
            }
        EXPECT_EQ(layer_wrong, 0) << "layer " << k << " of " << layers;
    }
}

}  // namespace

TEST(DepthRangesGL, HsmLevelsAreExact) {
    checkStructures(Accel::Hsm, 64, 64, 0);
}

// 6 layers (no whole-map layer): layer 0, then pairs 1-2, 3-4, then 5 alone.
TEST(DepthRangesGL, MssmLayersAreExact) {
    checkStructures(Accel::Mssm, 64, 64, 0);
}

// YSM parts skip layer 0: 4 layers (pair 1-2, then 3 alone), 5 layers (pairs 1-2, 3-4), and
// the YSM as large as the map (its MSSM part built from HSM level 0).
TEST(DepthRangesGL, YsmLayersAreExact) {
    checkStructures(Accel::Ysm, 64, 16, 1);
    checkStructures(Accel::Ysm, 128, 32, 1);
    checkStructures(Accel::Ysm, 32, 32, 1);
}
