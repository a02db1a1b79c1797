// The closed form of the light's share above a receiver's tangent plane (glsl/common/
// light_horizon.glsl, which shading, `ssm`, `css` and `bitmask` use), evaluated on the GL by a
// scratch compute shader and checked against the same integral in double precision.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include <unistd.h>

#include "gl_test_env.h"
#include "renderer/gl/handles.h"
#include "renderer/gl/program.h"

using namespace penumbra;

namespace {

// horizonArea(h0, hx, hy) for each plane (h0, hx, hy) on the GL, through a compute shader
// written beside a copy of the include in a scratch PENUMBRA_GLSL_DIR.
std::vector<float> glHorizonAreas(const std::vector<glm::vec4>& planes) {
    const std::string include = gl::shaderSource("common/light_horizon.glsl");
    const auto dir = std::filesystem::temp_directory_path() /
                     ("penumbra_light_horizon_" + std::to_string(getpid()));
    std::filesystem::create_directories(dir / "common");
    std::filesystem::create_directories(dir / "t");
    std::ofstream(dir / "common/light_horizon.glsl") << include;
    std::ofstream(dir / "t/horizon.comp")
        << "#version 450 core\nlayout(local_size_x = 64) in;\n"
           "#include \"common/light_horizon.glsl\"\n"
           "layout(std430, binding = 0) readonly buffer Planes { vec4 b_planes[]; };\n"
           "layout(std430, binding = 1) writeonly buffer Areas { float b_areas[]; };\n"
           "uniform int u_count;\n"
           "void main() {\n"
           "    int i = int(gl_GlobalInvocationID.x);\n"
           "    if (i >= u_count) return;\n"
           "    vec4 p = b_planes[i];\n"
           "    b_areas[i] = horizonArea(p.x, p.y, p.z);\n"
           "}\n";
    setenv("PENUMBRA_GLSL_DIR", dir.c_str(), 1);
    const gl::Program program = gl::buildProgram("light horizon test", {"t/horizon.comp"});
    unsetenv("PENUMBRA_GLSL_DIR");
    std::filesystem::remove_all(dir);

    const auto n = static_cast<GLsizeiptr>(planes.size());
    const gl::Buffer in = gl::createBuffer("horizon planes");
    const gl::Buffer out = gl::createBuffer("horizon areas");
    glNamedBufferStorage(in.id(), n * GLsizeiptr(sizeof(glm::vec4)), planes.data(), 0);
    glNamedBufferStorage(out.id(), n * GLsizeiptr(sizeof(float)), nullptr, GL_DYNAMIC_STORAGE_BIT);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, in.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, out.id());
    glUseProgram(program.id());
    gl::setUniform(program, "u_count", static_cast<int>(n));
    glDispatchCompute(static_cast<GLuint>((n + 63) / 64), 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    std::vector<float> areas(planes.size());
    glGetNamedBufferSubData(out.id(), 0, n * GLsizeiptr(sizeof(float)), areas.data());
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    return areas;
}

// The area of the unit square where h0 + hx x + hy y >= 0, in double precision: the covered
// length along the axis of the larger slope (x after a swap) by the midpoint rule over 4096
// strips across it. The length is piecewise linear with a slope of at most 1, so only the two
// strips with a kink err, by at most 1 / (8 4096^2) each.
double areaAbove(double h0, double hx, double hy) {
    if (std::fabs(hx) < std::fabs(hy)) std::swap(hx, hy);
    const int strips = 4096;
    double sum = 0.0;
    for (int j = 0; j < strips; ++j) {
        const double y = (j + 0.5) / strips, c = h0 + hy * y;  // c + hx x >= 0
        double len;
        if (hx == 0.0)
            len = c >= 0.0 ? 1.0 : 0.0;
        else if (hx > 0.0)
            len = 1.0 - std::clamp(-c / hx, 0.0, 1.0);
        else
            len = std::clamp(c / -hx, 0.0, 1.0);
        sum += len;
    }
    return sum / strips;
}

}  // namespace

TEST(LightHorizonGL, ThePlaneNearlyParallelToTheLightKeepsItWhole) {
    // A face parallel to the light whose normal is off by a float rounding (1e-7, as the
    // G-buffer's facet normal of a box's top seen at a grazing angle): the ramp's integral was
    // taken as a difference of two values near 1e7, float's spacing there 1, and gave 0 or 2
    // for 1: visibility 0 along rows of a lit table top (under_table at 160 x 120, `ssm` and
    // `css`), and beauty 0 where the shading normal had such an error.
    penumbra::testing::glInfo();
    std::vector<glm::vec4> planes;
    for (float h0 : {2.17f, 0.5f, -0.5f, -2.17f})
        for (float hx : {-2e-7f, 2e-7f, 1e-6f, -3e-5f, 1e-4f})
            for (float hy : {-2.1e-7f, 0.0f, 1.7e-7f, 2e-5f}) planes.emplace_back(h0, hx, hy, 0.0f);
    const std::vector<float> areas = glHorizonAreas(planes);
    for (size_t i = 0; i < planes.size(); ++i)
        EXPECT_EQ(areas[i], planes[i].x > 0.0f ? 1.0f : 0.0f)
            << "h0 " << planes[i].x << ", hx " << planes[i].y << ", hy " << planes[i].z;
}

TEST(LightHorizonGL, AnyPlaneCutsTheLightAsTheIntegralDoes) {
    // Planes across the light at every angle and offset, the ones of the near-parallel branch
    // (a slope ratio below 1e-3) among them; 2e-5 covers float rounding in the ramp.
    penumbra::testing::glInfo();
    std::mt19937 rng(19);
    std::uniform_real_distribution<float> any(-2.0f, 2.0f), small(-1e-4f, 1e-4f);
    std::vector<glm::vec4> planes;
    for (int i = 0; i < 2000; ++i) {
        const float hx = any(rng), hy = i % 4 == 0 ? small(rng) * hx : any(rng);
        planes.emplace_back(any(rng), hx, hy, 0.0f);
    }
    const std::vector<float> areas = glHorizonAreas(planes);
    double worst = 0.0;
    for (size_t i = 0; i < planes.size(); ++i) {
        const glm::vec4 p = planes[i];
        worst = std::max(worst, std::fabs(areas[i] - areaAbove(p.x, p.y, p.z)));
    }
    std::printf("closed form against the double integral: worst %.2g over %zu planes\n", worst,
                planes.size());
    EXPECT_LE(worst, 2e-5);
}
