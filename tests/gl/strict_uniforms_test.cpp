// Strict uniforms: setting a uniform that no shader of the program declares (a misspelling, or a
// value the host sets in vain) throws while the GL tests run; a declared uniform the compiler
// removed stays a silent no-op, in every mode.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include <unistd.h>

#include "gl_test_env.h"
#include "renderer/gl/program.h"

using namespace penumbra;

namespace {

// A program from a vertex and a fragment shader written to a scratch glsl/ folder (the
// PENUMBRA_GLSL_DIR development path), its fragment shader declaring u_dead and never reading
// it.
gl::Program scratchProgram() {
    // A folder per process: ctest runs this file's tests in parallel, and one test's
    // remove_all below took the shaders from under another (PENUMBRA_GLSL_DIR: cannot read).
    const auto dir = std::filesystem::temp_directory_path() /
                     ("penumbra_strict_uniforms_" + std::to_string(getpid()));
    std::filesystem::create_directories(dir / "t");
    std::ofstream(dir / "t/a.vert") << "#version 450 core\nuniform float u_scale;\n"
                                       "void main() { gl_Position = vec4(u_scale); }\n";
    std::ofstream(dir / "t/a.frag") << "#version 450 core\nuniform int u_dead;\n"
                                       "uniform vec3 u_colour;\nout vec4 o;\n"
                                       "void main() { o = vec4(u_colour, 1.0); }\n";
    setenv("PENUMBRA_GLSL_DIR", dir.c_str(), 1);
    gl::Program p = gl::buildProgram("strict test", {"t/a.vert", "t/a.frag"});
    unsetenv("PENUMBRA_GLSL_DIR");
    std::filesystem::remove_all(dir);
    return p;
}

}  // namespace

TEST(StrictUniforms, OnInTheGlTests) {
    penumbra::testing::glInfo();
    EXPECT_TRUE(gl::strictUniforms());
}

TEST(StrictUniforms, AMisspelledNameFails) {
    penumbra::testing::glInfo();
    const gl::Program p = scratchProgram();
    EXPECT_NO_THROW(gl::setUniform(p, "u_scale", 1.0f));
    EXPECT_NO_THROW(gl::setUniform(p, "u_colour", glm::vec3(1.0f)));
    EXPECT_NO_THROW(gl::setUniform(p, "u_dead", 3));  // declared, optimised out: no error
    try {
        gl::setUniform(p, "u_color", glm::vec3(1.0f));
        FAIL() << "a misspelled uniform was ignored";
    } catch (const std::logic_error& e) {
        EXPECT_NE(std::string(e.what()).find("program strict test"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("'u_color'"), std::string::npos) << e.what();
    }
    EXPECT_THROW(gl::setUniform(p, "u_scael", 1.0f), std::logic_error);
}

TEST(StrictUniforms, OffIgnoresUnknownNames) {
    penumbra::testing::glInfo();
    const gl::Program p = scratchProgram();
    gl::setStrictUniforms(false);
    EXPECT_NO_THROW(gl::setUniform(p, "u_color", glm::vec3(1.0f)));
    gl::setStrictUniforms(true);
}

TEST(StrictUniforms, TheProgramsUniformsAreKnown) {
    penumbra::testing::glInfo();
    const gl::Program p = scratchProgram();
    EXPECT_EQ(gl::programUniforms(p), (std::set<std::string>{"u_scale", "u_dead", "u_colour"}));
}
