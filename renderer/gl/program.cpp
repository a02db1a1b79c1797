// Shader sources, program building and uniform setters: see program.h.
#include "renderer/gl/program.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <fstream>
#include <map>
#include <regex>
#include <span>
#include <sstream>
#include <stdexcept>

#include "renderer/core/error.h"
#include "renderer/gl/program_cache.h"

namespace penumbra::shaders {
extern const std::pair<std::string_view, std::string_view> kEmbedded[];
extern const std::size_t kEmbeddedCount;
}  // namespace penumbra::shaders

namespace penumbra::gl {
namespace {

bool g_strict = false;

// What buildProgram learnt of each program it linked (by GL name; a recycled name is
// overwritten when its new program is built).
struct ProgramRecord {
    std::string label;
    std::set<std::string> uniforms;
};
std::map<GLuint, ProgramRecord>& programRecords() {
    static std::map<GLuint, ProgramRecord> records;
    return records;
}

bool identifierChar(char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
}

// The identifier that ends DECLARATOR (one of `T a[2] = x, b`'s comma-separated parts, its
// array size and initialiser cut off).
std::string declaredName(std::string_view declarator) {
    declarator = declarator.substr(0, std::min(declarator.find('='), declarator.find('[')));
    size_t end = declarator.size();
    while (end > 0 && !identifierChar(declarator[end - 1])) --end;
    size_t begin = end;
    while (begin > 0 && identifierChar(declarator[begin - 1])) --begin;
    return std::string(declarator.substr(begin, end - begin));
}

std::string withoutComments(std::string_view source) {
    std::string out;
    for (size_t i = 0; i < source.size(); ++i) {
        if (source.compare(i, 2, "//") == 0) {
            i = std::min(source.find('\n', i), source.size()) - 1;
            out += ' ';
        } else if (source.compare(i, 2, "/*") == 0) {
            i = std::min(source.find("*/", i + 2), source.size() - 2) + 1;
            out += ' ';
        } else {
            out += source[i];
        }
    }
    return out;
}

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

std::vector<std::string_view> embeddedShaderNames() {
    std::vector<std::string_view> names;
    for (std::size_t i = 0; i < shaders::kEmbeddedCount; ++i)
        if (!shaders::kEmbedded[i].first.empty()) names.push_back(shaders::kEmbedded[i].first);
    return names;
}

std::set<std::string> declaredUniforms(std::string_view source) {
    const std::string text = withoutComments(source);
    std::set<std::string> names;
    size_t at = 0;
    while ((at = text.find("uniform", at)) != std::string::npos) {
        const size_t after = at + 7;
        const bool word = (at == 0 || !identifierChar(text[at - 1])) &&
                          (after >= text.size() || !identifierChar(text[after]));
        at = after;
        if (!word) continue;
        const size_t end = text.find_first_of(";{", after);
        if (end == std::string::npos || text[end] == '{') continue;  // a uniform block
        std::string_view decl(text.data() + after, end - after);
        // Commas inside an initialiser's parentheses do not separate declarators.
        int depth = 0;
        size_t start = 0;
        for (size_t i = 0; i <= decl.size(); ++i) {
            if (i < decl.size() && (decl[i] == '(' || decl[i] == '[')) ++depth;
            if (i < decl.size() && (decl[i] == ')' || decl[i] == ']')) --depth;
            if (i == decl.size() || (decl[i] == ',' && depth == 0)) {
                if (std::string name = declaredName(decl.substr(start, i - start)); !name.empty())
                    names.insert(std::move(name));
                start = i + 1;
            }
        }
    }
    return names;
}

const std::set<std::string>& programUniforms(const Program& program) {
    static const std::set<std::string> none;
    auto it = programRecords().find(program.id());
    return it == programRecords().end() ? none : it->second.uniforms;
}

void setStrictUniforms(bool strict) {
    g_strict = strict;
}
bool strictUniforms() {
    return g_strict;
}

std::string shaderSource(std::string_view name) {
    if (const char* dir = std::getenv("PENUMBRA_GLSL_DIR"); dir && *dir)
        return readDiskShader(dir, std::string(name), 0);
    for (std::size_t i = 0; i < shaders::kEmbeddedCount; ++i)
        if (shaders::kEmbedded[i].first == name) return std::string(shaders::kEmbedded[i].second);
    throw RuntimeError("glsl/" + std::string(name) + ": no such embedded shader");
}

namespace {

// Compiles and links SOURCES (stage name, source) into PROGRAM. Throws RuntimeError with the log.
void compileAndLink(const Program& program, std::string_view label,
                    const std::vector<std::pair<std::string_view, std::string>>& sources) {
    std::vector<GLuint> shaders;
    auto cleanup = [&] {
        for (GLuint s : shaders) glDeleteShader(s);
    };
    for (const auto& [name, src] : sources) {
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
    if (!programCacheFolder().empty())
        glProgramParameteri(program.id(), GL_PROGRAM_BINARY_RETRIEVABLE_HINT, GL_TRUE);
    glLinkProgram(program.id());
    GLint ok = 0;
    glGetProgramiv(program.id(), GL_LINK_STATUS, &ok);
    for (GLuint s : shaders) glDetachShader(program.id(), s);
    cleanup();
    if (!ok) {
        GLint len = 0;
        glGetProgramiv(program.id(), GL_INFO_LOG_LENGTH, &len);
        std::string log(static_cast<size_t>(std::max(len, 1)), '\0');
        glGetProgramInfoLog(program.id(), len, nullptr, log.data());
        throw RuntimeError("program " + std::string(label) + ": link failed: " + log);
    }
}

}  // namespace

Program buildProgram(std::string_view label, std::initializer_list<std::string_view> stages,
                     const Defines& defines) {
    Program program(glCreateProgram(), label);
    ProgramRecord record{std::string(label), {}};
    std::vector<std::pair<std::string_view, std::string>> sources;
    std::string key;  // the program cache's: every stage's name and source
    for (std::string_view name : stages) {
        std::string src = injectDefines(shaderSource(name), defines);
        record.uniforms.merge(declaredUniforms(src));
        key.append(name).append(1, '\0').append(src).append(1, '\0');
        sources.emplace_back(name, std::move(src));
    }
    if (!loadCachedProgram(program.id(), key)) {
        compileAndLink(program, label, sources);
        countCompiledProgram();
        storeCachedProgram(program.id(), key);
    }
    programRecords()[program.id()] = std::move(record);
    return program;
}

namespace {
// The location of NAME in P, or -1 for a declared uniform the compiler removed. In strict mode a
// name P's shaders do not declare (a misspelling, or one the C++ side sets in vain) throws.
GLint uniformLocation(const Program& p, const char* name) {
    const GLint loc = glGetUniformLocation(p.id(), name);
    if (loc < 0 && g_strict) {
        auto it = programRecords().find(p.id());
        std::string base(name);
        base = base.substr(0, base.find('['));
        if (it == programRecords().end() || !it->second.uniforms.count(base))
            throw std::logic_error(
                "program " + (it == programRecords().end() ? std::string("?") : it->second.label) +
                ": setUniform: its shaders declare no uniform '" + std::string(name) + "'");
    }
    return loc;
}
}  // namespace

#define PENUMBRA_UNIFORM(T, CALL)                              \
    void setUniform(const Program& p, const char* name, T v) { \
        GLint loc = uniformLocation(p, name);                  \
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
