// GLSL programs from the embedded glsl/ tree (or from disk when PENUMBRA_GLSL_DIR is set, for
// shader development), with variant #defines injected by the host after the #version line.
#pragma once

#include <glm/glm.hpp>

#include <initializer_list>
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

// Uniform setters by name (ignored when the uniform is inactive).
void setUniform(const Program& p, const char* name, int v);
void setUniform(const Program& p, const char* name, float v);
void setUniform(const Program& p, const char* name, const glm::vec2& v);
void setUniform(const Program& p, const char* name, const glm::vec3& v);
void setUniform(const Program& p, const char* name, const glm::vec4& v);
void setUniform(const Program& p, const char* name, const glm::ivec2& v);
void setUniform(const Program& p, const char* name, const glm::mat4& v);
void setUniform(const Program& p, const char* name, const glm::mat3& v);

}  // namespace penumbra::gl
