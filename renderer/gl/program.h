// GLSL programs from the embedded glsl/ tree (or from disk when PENUMBRA_GLSL_DIR is set, for
// shader development), with variant #defines injected by the host after the #version line.
#pragma once

#include <glm/glm.hpp>

#include <initializer_list>
#include <set>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "renderer/gl/handles.h"

namespace penumbra::gl {

using Defines = std::vector<std::pair<std::string, std::string>>;

// The source of glsl/NAME with includes resolved. Throws RuntimeError if unknown.
std::string shaderSource(std::string_view name);

// Compiles and links the entry points STAGES (e.g. {"passes/gbuffer.vert",
// "passes/gbuffer.frag"}; the stage follows the extension). Throws RuntimeError with the log.
Program buildProgram(std::string_view label, std::initializer_list<std::string_view> stages,
                     const Defines& defines = {});

// The names of the embedded shaders (glsl/, relative), for tests that read them all.
std::vector<std::string_view> embeddedShaderNames();

// The names SOURCE declares as plain uniforms (`uniform T name;`, arrays by their name; not
// uniform blocks), whatever preprocessor branch they sit in.
std::set<std::string> declaredUniforms(std::string_view source);
// The uniforms declared by the sources PROGRAM was built from (empty for a program not made by
// buildProgram).
const std::set<std::string>& programUniforms(const Program& program);

// Strict uniforms (process-wide; off by default): setUniform on a name that PROGRAM's shaders do
// not declare throws std::logic_error instead of being ignored. A declared uniform the compiler
// optimised out in one variant stays a silent no-op. On under --gl-debug and in the GL tests.
void setStrictUniforms(bool strict);
bool strictUniforms();

// Uniform setters by name (ignored when the uniform is inactive; see setStrictUniforms).
void setUniform(const Program& p, const char* name, int v);
void setUniform(const Program& p, const char* name, float v);
void setUniform(const Program& p, const char* name, const glm::vec2& v);
void setUniform(const Program& p, const char* name, const glm::vec3& v);
void setUniform(const Program& p, const char* name, const glm::vec4& v);
void setUniform(const Program& p, const char* name, const glm::ivec2& v);
void setUniform(const Program& p, const char* name, const glm::mat4& v);
void setUniform(const Program& p, const char* name, const glm::mat3& v);

}  // namespace penumbra::gl
