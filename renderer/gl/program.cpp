// Shader sources, program building and uniform setters: see program.h.
#include "renderer/gl/program.h"

#include <glm/gtc/type_ptr.hpp>

#include <cstdlib>
#include <fstream>
#include <regex>
#include <span>
#include <sstream>

#include "renderer/core/error.h"

namespace penumbra::shaders {
extern const std::pair<std::string_view, std::string_view> kEmbedded[];
extern const std::size_t kEmbeddedCount;
}  // namespace penumbra::shaders

namespace penumbra::gl {
namespace {

std::string readDiskShader(const std::string& root, const std::string& name, int depth) {
    if (depth > 16) throw RuntimeError("glsl/" + name + ": #include nested too deeply");
    std::ifstream in(root + "/" + name);
    if (!in) throw RuntimeError("PENUMBRA_GLSL_DIR: cannot read " + root + "/" + name);
    static const std::regex include(R"re(^\s*#\s*include\s+"([^"]+)"\s*$)re");
    std::string line, out;
    std::smatch m;
    while (std::getline(in, line)) {
        if (std::regex_match(line, m, include))
            out += readDiskShader(root, m[1].str(), depth + 1);
        else
            out += line + "\n";
    }
    return out;
}

GLenum stageOf(std::string_view name) {
    if (name.ends_with(".vert")) return GL_VERTEX_SHADER;
    if (name.ends_with(".frag")) return GL_FRAGMENT_SHADER;
    if (name.ends_with(".comp")) return GL_COMPUTE_SHADER;
    if (name.ends_with(".geom")) return GL_GEOMETRY_SHADER;
    throw RuntimeError("glsl/" + std::string(name) + ": not an entry point");
}

std::string injectDefines(const std::string& source, const Defines& defines) {
    std::string block;
    for (const auto& [k, v] : defines) block += "#define " + k + " " + v + "\n";
    size_t pos = source.find("#version");
    size_t eol = pos == std::string::npos ? 0 : source.find('\n', pos);
    if (pos == std::string::npos || eol == std::string::npos) return block + source;
    return source.substr(0, eol + 1) + block + source.substr(eol + 1);
}

}  // namespace

std::string shaderSource(std::string_view name) {
    if (const char* dir = std::getenv("PENUMBRA_GLSL_DIR"); dir && *dir)
        return readDiskShader(dir, std::string(name), 0);
    for (std::size_t i = 0; i < shaders::kEmbeddedCount; ++i)
        if (shaders::kEmbedded[i].first == name) return std::string(shaders::kEmbedded[i].second);
    throw RuntimeError("glsl/" + std::string(name) + ": no such embedded shader");
}

Program buildProgram(std::string_view label, std::initializer_list<std::string_view> stages,
                     const Defines& defines) {
    Program program(glCreateProgram(), label);
    std::vector<GLuint> shaders;
    auto cleanup = [&] {
        for (GLuint s : shaders) glDeleteShader(s);
    };
    for (std::string_view name : stages) {
        std::string src = injectDefines(shaderSource(name), defines);
        GLuint s = glCreateShader(stageOf(name));
        shaders.push_back(s);
        const char* text = src.c_str();
        glShaderSource(s, 1, &text, nullptr);
        glCompileShader(s);
        GLint ok = 0;
        glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
        if (!ok) {
            GLint len = 0;
            glGetShaderiv(s, GL_INFO_LOG_LENGTH, &len);
            std::string log(static_cast<size_t>(std::max(len, 1)), '\0');
            glGetShaderInfoLog(s, len, nullptr, log.data());
            cleanup();
            throw RuntimeError("glsl/" + std::string(name) + ": compile failed: " + log);
        }
        glAttachShader(program.id(), s);
    }
    glLinkProgram(program.id());
    GLint ok = 0;
    glGetProgramiv(program.id(), GL_LINK_STATUS, &ok);
    cleanup();
    if (!ok) {
        GLint len = 0;
        glGetProgramiv(program.id(), GL_INFO_LOG_LENGTH, &len);
        std::string log(static_cast<size_t>(std::max(len, 1)), '\0');
        glGetProgramInfoLog(program.id(), len, nullptr, log.data());
        throw RuntimeError("program " + std::string(label) + ": link failed: " + log);
    }
    return program;
}

#define PENUMBRA_UNIFORM(T, CALL)                              \
    void setUniform(const Program& p, const char* name, T v) { \
        GLint loc = glGetUniformLocation(p.id(), name);        \
        if (loc >= 0) CALL;                                    \
    }
PENUMBRA_UNIFORM(int, glProgramUniform1i(p.id(), loc, v))
PENUMBRA_UNIFORM(float, glProgramUniform1f(p.id(), loc, v))
PENUMBRA_UNIFORM(const glm::vec2&, glProgramUniform2fv(p.id(), loc, 1, glm::value_ptr(v)))
PENUMBRA_UNIFORM(const glm::vec3&, glProgramUniform3fv(p.id(), loc, 1, glm::value_ptr(v)))
PENUMBRA_UNIFORM(const glm::vec4&, glProgramUniform4fv(p.id(), loc, 1, glm::value_ptr(v)))
PENUMBRA_UNIFORM(const glm::ivec2&, glProgramUniform2iv(p.id(), loc, 1, glm::value_ptr(v)))
PENUMBRA_UNIFORM(const glm::mat4&,
                 glProgramUniformMatrix4fv(p.id(), loc, 1, GL_FALSE, glm::value_ptr(v)))
PENUMBRA_UNIFORM(const glm::mat3&,
                 glProgramUniformMatrix3fv(p.id(), loc, 1, GL_FALSE, glm::value_ptr(v)))
#undef PENUMBRA_UNIFORM

}  // namespace penumbra::gl
