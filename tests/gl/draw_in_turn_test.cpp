// passes::drawInTurn: each draw writes only the pixels no earlier draw settled (kept), the
// pixels a draw discards go on to the next, and the depth state is as it was afterwards.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "gl_test_env.h"
#include "renderer/gl/debug.h"
#include "renderer/gl/program.h"
#include "renderer/passes/cover_depth.h"
#include "renderer/passes/fullscreen.h"

using namespace penumbra;

namespace {

// Draw D (u_draw) settles: 0 the left half, 1 the bottom half, 2 every pixel; each writes D + 1.
gl::Program settlingProgram() {
    return penumbra::testing::linkTestProgram(
        "draw in turn test", {{GL_VERTEX_SHADER, gl::shaderSource("passes/fullscreen.vert")},
                              {GL_FRAGMENT_SHADER, R"(#version 450 core
uniform int u_draw;
uniform int u_half;
layout(location = 0) out vec4 o_value;
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    bool settles = u_draw == 0 ? p.x < u_half : (u_draw == 1 ? p.y < u_half : true);
    if (!settles) discard;
    o_value = vec4(float(u_draw + 1), 0.0, 0.0, 1.0);
}
)"}});
}

}  // namespace

TEST(DrawInTurnGL, EachDrawWritesOnlyThePixelsNoEarlierDrawSettled) {
    penumbra::testing::glInfo();
    const int size = 16, half = 8;
    gl::Texture target = gl::createTexture2D(GL_R32F, size, size, "draw in turn target");
    gl::Framebuffer fbo = gl::createFramebuffer("draw in turn");
    glNamedFramebufferTexture(fbo.id(), GL_COLOR_ATTACHMENT0, target.id(), 0);
    passes::CoverDepth depth("draw in turn depth");
    depth.attach(fbo.id(), size, size);
    ASSERT_EQ(glCheckNamedFramebufferStatus(fbo.id(), GL_FRAMEBUFFER),
              GLenum(GL_FRAMEBUFFER_COMPLETE));
    const gl::Program program = settlingProgram();
    passes::Fullscreen fullscreen;
    glBindFramebuffer(GL_FRAMEBUFFER, fbo.id());
    glViewport(0, 0, size, size);
    // Twice: the second time also checks that the depth of the first was cleared.
    for (int round = 0; round < 2; ++round) {
        const float zero[4] = {0, 0, 0, 0};
        glClearBufferfv(GL_COLOR, 0, zero);
        glUseProgram(program.id());
        gl::setUniform(program, "u_half", half);
        const auto draw = [&](int d) {
            gl::setUniform(program, "u_draw", d);
            fullscreen.draw();
        };
        glDepthMask(GL_FALSE);  // a pass before left it off: the clear must still happen
        glDepthFunc(GL_GREATER);
        passes::drawInTurn({[&] { draw(0); }, [&] { draw(1); }, [&] { draw(2); }});
        EXPECT_FALSE(glIsEnabled(GL_DEPTH_TEST));
        GLboolean mask = GL_TRUE;
        GLint func = 0;
        glGetBooleanv(GL_DEPTH_WRITEMASK, &mask);
        glGetIntegerv(GL_DEPTH_FUNC, &func);
        EXPECT_EQ(mask, GL_FALSE);
        EXPECT_EQ(func, GL_GREATER);
        std::vector<float> got(size_t(size * size));
        glGetTextureImage(target.id(), 0, GL_RED, GL_FLOAT, GLsizei(got.size() * sizeof(float)),
                          got.data());
        for (int y = 0; y < size; ++y)
            for (int x = 0; x < size; ++x) {
                const float want = x < half ? 1.0f : (y < half ? 2.0f : 3.0f);
                EXPECT_EQ(got[size_t(y * size + x)], want) << "pixel " << x << "," << y;
            }
    }
    glDepthMask(GL_TRUE);  // GL's defaults again, for the tests after this one
    glDepthFunc(GL_LESS);
    glUseProgram(0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    passes::CoverDepth::detach(fbo.id());
    gl::checkErrors("draw in turn test");
}
