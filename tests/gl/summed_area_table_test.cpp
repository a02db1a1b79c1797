// The summed-area table pass against sums in double precision on the CPU: zero first row and
// column, exact integer sums, the FP32 error of centred values, and the unsigned variant.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "gl_test_env.h"
#include "renderer/gl/debug.h"
#include "renderer/passes/summed_area_table.h"

using namespace penumbra;

namespace {

// Builds the SAT of SOURCE (SIZE^2 x LAYERS RGBA texels) and returns it ((SIZE+1)^2 per layer).
std::vector<float> buildTable(const std::vector<float>& source, int size, int layers) {
    penumbra::testing::glInfo();
    gl::Texture tex = gl::createTexture2DArray(GL_RGBA32F, size, size, layers, "sat source");
    glTextureSubImage3D(tex.id(), 0, 0, 0, 0, size, size, layers, GL_RGBA, GL_FLOAT, source.data());
    passes::SummedAreaTable sat(size, layers, "sat test");
    sat.build(tex);
    std::vector<float> out(static_cast<size_t>((size + 1) * (size + 1) * layers * 4));
    glGetTextureImage(sat.table().id(), 0, GL_RGBA, GL_FLOAT,
                      static_cast<GLsizei>(out.size() * sizeof(float)), out.data());
    gl::checkErrors("sat test");
    return out;
}

}  // namespace

TEST(SummedAreaTableGL, MatchesDoubleSums) {
    const int size = 48, layers = 2;
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> value(-1.0f, 1.0f);
    std::vector<float> src(static_cast<size_t>(size * size * layers * 4));
    for (auto& v : src) v = value(rng);
    const auto table = buildTable(src, size, layers);
    const int n1 = size + 1;
    double max_error = 0;
    for (int l = 0; l < layers; ++l)
        for (int c = 0; c < 4; ++c) {
            std::vector<double> s(static_cast<size_t>(n1 * n1), 0.0);
            for (int y = 1; y < n1; ++y)
                for (int x = 1; x < n1; ++x) {
                    const double v =
                        src[static_cast<size_t>(((l * size + y - 1) * size + x - 1) * 4 + c)];
                    s[size_t(y * n1 + x)] = v + s[size_t((y - 1) * n1 + x)] +
                                            s[size_t(y * n1 + x - 1)] -
                                            s[size_t((y - 1) * n1 + x - 1)];
                }
            for (int y = 0; y < n1; ++y)
                for (int x = 0; x < n1; ++x) {
                    const float got = table[static_cast<size_t>(((l * n1 + y) * n1 + x) * 4 + c)];
                    if (x == 0 || y == 0) {
                        EXPECT_EQ(got, 0.0f) << x << "," << y;
                    }
                    max_error = std::max(max_error, std::fabs(got - s[size_t(y * n1 + x)]));
                }
        }
    // Centred values (mean 0) keep the sums near sqrt(area): FP32 sums of at most 2304 terms
    // of magnitude <= 1 are off by a few 1e-6 per term at worst; 1e-3 is far above that and far
    // below one texel's value.
    EXPECT_LE(max_error, 1e-3);
}

// The unsigned table (bitmask's caster sums) against sums in uint32 arithmetic: exact, wrapping
// at 2^32 (values up to 2^28 over 40 x 40 texels overflow), so a box's four-corner difference
// gives its own sum back.
TEST(SummedAreaTableGL, UnsignedSumsAreExactAndWrap) {
    penumbra::testing::glInfo();
    const int size = 40, layers = 2, n1 = size + 1;
    std::mt19937 rng(11);
    std::uniform_int_distribution<std::uint32_t> value(0u, 1u << 28);
    std::vector<std::uint32_t> src(static_cast<size_t>(size * size * layers * 4));
    for (auto& v : src) v = value(rng);
    gl::Texture tex = gl::createTexture2DArray(GL_RGBA32UI, size, size, layers, "sat source");
    glTextureSubImage3D(tex.id(), 0, 0, 0, 0, size, size, layers, GL_RGBA_INTEGER, GL_UNSIGNED_INT,
                        src.data());
    passes::SummedAreaTable sat(size, layers, "sat test", passes::SummedAreaTable::Texel::Unsigned);
    sat.build(tex);
    std::vector<std::uint32_t> table(static_cast<size_t>(n1 * n1 * layers * 4));
    glGetTextureImage(sat.table().id(), 0, GL_RGBA_INTEGER, GL_UNSIGNED_INT,
                      static_cast<GLsizei>(table.size() * sizeof(std::uint32_t)), table.data());
    gl::checkErrors("unsigned sat test");
    bool wrapped = false;
    int mismatches = 0;
    for (int l = 0; l < layers; ++l)
        for (int c = 0; c < 4; ++c)
            for (int y = 0; y < n1; ++y)
                for (int x = 0; x < n1; ++x) {
                    std::uint32_t want = 0;
                    std::uint64_t wide = 0;
                    for (int j = 0; j < y; ++j)
                        for (int i = 0; i < x; ++i) {
                            const auto v =
                                src[static_cast<size_t>(((l * size + j) * size + i) * 4 + c)];
                            want += v;
                            wide += v;
                        }
                    wrapped = wrapped || wide > 0xffffffffu;
                    const auto got = table[static_cast<size_t>(((l * n1 + y) * n1 + x) * 4 + c)];
                    if (got != want) ++mismatches;
                }
    EXPECT_EQ(mismatches, 0);
    EXPECT_TRUE(wrapped);  // the test reaches the wrap it is about
    // A 5 x 3 box (texels [7, 12) x [20, 23) of layer 1, channel 2) from its four corners.
    auto at = [&](int x, int y) {
        return table[static_cast<size_t>(((1 * n1 + y) * n1 + x) * 4 + 2)];
    };
    std::uint32_t box = 0;
    for (int j = 20; j < 23; ++j)
        for (int i = 7; i < 12; ++i)
            box += src[static_cast<size_t>(((size + j) * size + i) * 4 + 2)];
    EXPECT_EQ(at(12, 23) - at(7, 23) - at(12, 20) + at(7, 20), box);
}
