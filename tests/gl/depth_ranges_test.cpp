// `bitmask`'s acceleration structures against brute force on the CPU: every HSM level and
// every MSSM / YSM layer a query can reach holds the exact (min, max) of its texels, and the
// MSSM query (mssm_range.glsl) returns the exact range of the texels it covers, for any texel
// range up to the whole map.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <random>
#include <vector>

#include "gl_test_env.h"
#include "renderer/gl/debug.h"
#include "renderer/gl/program.h"
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

// 5 layers (none of the two widest): layer 0, then pairs 1-2, 3-4.
TEST(DepthRangesGL, MssmLayersAreExact) {
    checkStructures(Accel::Mssm, 64, 64, 0);
}

// YSM parts skip layer 0: 3 layers (pair 1-2), 4 layers (pair 1-2, then 3 alone), and the YSM
// as large as the map (its MSSM part built from HSM level 0).
TEST(DepthRangesGL, YsmLayersAreExact) {
    checkStructures(Accel::Ysm, 64, 16, 1);
    checkStructures(Accel::Ysm, 128, 32, 1);
    checkStructures(Accel::Ysm, 32, 32, 1);
}

namespace {

// A compute program running mssmRange (mssm_range.glsl) on the inclusive ranges of binding 0
// (ivec4 each), writing (min, max) to binding 1.
gl::Program queryProgram() {
    const std::string source =
        "#version 450 core\n" + gl::shaderSource("techniques/bitmask/mssm_range.glsl") + R"(
layout(local_size_x = 64) in;
layout(binding = 0) uniform sampler2DArray u_mssm;
layout(std430, binding = 0) readonly buffer Queries { ivec4 queries[]; };
layout(std430, binding = 1) writeonly buffer Results { vec2 results[]; };
void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i < uint(queries.length())) results[i] = mssmRange(u_mssm, queries[i]);
}
)";
    return penumbra::testing::linkTestProgram("mssm query test", {{GL_COMPUTE_SHADER, source}});
}

// A SIZE^2 map of distances in [1, 9] but for one texel nearer (0.5) and one farther (10), at
// random: a query whose coverage misses one of them returns the wrong range.
std::vector<float> spikedMap(int size, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> dist(1.0f, 9.0f);
    std::uniform_int_distribution<int> texel(0, size * size - 1);
    std::vector<float> rg(static_cast<size_t>(size * size * 2));
    for (size_t i = 0; i < rg.size(); i += 2) rg[i] = rg[i + 1] = dist(rng);
    rg[size_t(texel(rng) * 2)] = 0.5f;
    rg[size_t(texel(rng) * 2 + 1)] = 10.0f;
    return rg;
}

// PROGRAM's (queryProgram()) answers to QUERIES (inclusive ranges, 4 ints each) over RANGES'
// MSSM.
std::vector<float> runQueries(const gl::Program& program, const DepthRanges& ranges,
                              const std::vector<int>& queries) {
    const int count = static_cast<int>(queries.size() / 4);
    gl::Buffer in = gl::createBuffer("mssm queries"), out = gl::createBuffer("mssm results");
    glNamedBufferStorage(in.id(), static_cast<GLsizeiptr>(queries.size() * sizeof(int)),
                         queries.data(), 0);
    glNamedBufferStorage(out.id(), static_cast<GLsizeiptr>(count * 2 * sizeof(float)), nullptr,
                         GL_DYNAMIC_STORAGE_BIT);
    glUseProgram(program.id());
    glBindTextureUnit(0, ranges.mssm().id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, in.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, out.id());
    glDispatchCompute(static_cast<GLuint>((count + 63) / 64), 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    std::vector<float> got(static_cast<size_t>(count * 2));
    glGetNamedBufferSubData(out.id(), 0, static_cast<GLsizeiptr>(got.size() * sizeof(float)),
                            got.data());
    glUseProgram(0);
    gl::checkErrors("mssm query test");
    return got;
}

}  // namespace

// Random ranges of every width up to the whole map, which the layers built (up to log2(size) -
// 2) serve with up to 4 x 4 neighbourhoods, on 8 maps with a near and a far spike each, against
// brute force over level 0: exact along the longer axis, and along the shorter one over the
// neighbourhoods' width from its start.
TEST(DepthRangesGL, MssmQueriesAreExactUpToTheWholeMap) {
    penumbra::testing::glInfo();
    const int size = 64;
    std::mt19937 rng(11);
    std::vector<int> queries;
    for (int n = 0; n < 1000; ++n) {
        // Widths spread over every power of two; every other query wider than two top-layer
        // neighbourhoods (33 .. 64 texels), the whole map included.
        std::uniform_int_distribution<int> any(1, size), wide_side(size / 2 + 1, size);
        const int w = n % 2 ? wide_side(rng) : any(rng);
        const int h = n % 2 ? wide_side(rng) : any(rng);
        const int x = std::uniform_int_distribution<int>(0, size - w)(rng);
        const int y = std::uniform_int_distribution<int>(0, size - h)(rng);
        queries.insert(queries.end(), {x, y, x + w - 1, y + h - 1});
    }
    queries.insert(queries.end(), {0, 0, size - 1, size - 1});
    const int count = static_cast<int>(queries.size() / 4);
    DepthRanges ranges(size, Accel::Mssm, size);
    ASSERT_EQ(ranges.mssmLayers(), 5);  // layers 0 .. log2(64) - 2
    const int top = ranges.mssmLayers() - 1;
    const gl::Program program = queryProgram();
    int wrong = 0, wide = 0, spikes_inside = 0;
    for (unsigned seed = 1; seed <= 8; ++seed) {
        const auto map = spikedMap(size, seed);
        glTextureSubImage2D(ranges.hsm().id(), 0, 0, 0, size, size, GL_RG, GL_FLOAT, map.data());
        ranges.buildHsm();
        ranges.buildMssm();
        const auto got = runQueries(program, ranges, queries);
        for (int i = 0; i < count; ++i) {
            const int* q = &queries[size_t(i * 4)];
            // The neighbourhoods' width: the range's shorter axis grows to it.
            const int extent = std::max(q[2] - q[0], q[3] - q[1]) + 1;
            const int k = std::min(int(std::bit_width(unsigned(extent))) - 1, top);
            const int x1 = std::min(std::max(q[2], q[0] + (1 << k) - 1), size - 1);
            const int y1 = std::min(std::max(q[3], q[1] + (1 << k) - 1), size - 1);
            Range r;
            for (int y = q[1]; y <= y1; ++y)
                for (int x = q[0]; x <= x1; ++x) {
                    r.lo = std::min(r.lo, map[size_t((y * size + x) * 2)]);
                    r.hi = std::max(r.hi, map[size_t((y * size + x) * 2 + 1)]);
                }
            wrong += got[size_t(i * 2)] != r.lo || got[size_t(i * 2 + 1)] != r.hi;
            wide += extent > 2 << top;
            spikes_inside += (extent > 2 << top) * ((r.lo == 0.5f) + (r.hi == 10.0f));
        }
    }
    // Ranges wider than two top-layer neighbourhoods, and spikes inside them to miss.
    EXPECT_GT(wide, 8 * 450);
    EXPECT_GT(spikes_inside, 8 * 450);
    EXPECT_EQ(wrong, 0) << "of " << 8 * count << " queries";
}
