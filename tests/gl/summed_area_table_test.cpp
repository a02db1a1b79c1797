// The summed-area table pass against sums in double precision on the CPU: zero first row and
// column, exact integer sums, and the FP32 error of centred values.
#include <gtest/gtest.h>

#include <cmath>
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
