// How parameters and bindings reach the shaders, checked without a context: every parameter a
// table marks `uniform` is declared with a matching type by its technique's shaders, every
// `define` is read by them; binding points are named constants of the bindings headers that
// GLSL and C++ both include, never literal numbers on either side.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>

#include "renderer/gl/param_uniforms.h"
#include "renderer/gl/program.h"
#include "renderer/passes/bindings.h"
#include "renderer/techniques/technique.h"

using namespace penumbra;

namespace {

// The sources (includes resolved) of the shaders a technique's programs are built from: its own
// folder's and the shared passes' and common ones.
std::string shadersOf(std::string_view technique) {
    std::string all;
    for (std::string_view name : gl::embeddedShaderNames())
        if (name.starts_with("techniques/" + std::string(technique) + "/") ||
            name.starts_with("passes/") || name.starts_with("common/"))
            all += gl::shaderSource(name) + "\n";
    return all;
}

std::string readFile(const std::filesystem::path& path) {
    std::ifstream in(path);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

}  // namespace

TEST(GpuParams, DeclaredUniformsAreFound) {
    const auto names = gl::declaredUniforms(
        "layout(binding = 3) uniform sampler2D u_a;  // uniform int u_comment;\n"
        "uniform int u_b = -1, u_c;\nuniform vec2 u_d[4];\n/* uniform float u_e; */\n"
        "layout(std140) uniform Block { int u_member; };\nfloat uniformity;\n"
        "#if X\nuniform float u_f;\n#endif\n");
    EXPECT_EQ(names, (std::set<std::string>{"u_a", "u_b", "u_c", "u_d", "u_f"}));
}

TEST(GpuParams, UniformParametersAreDeclaredWithTheirType) {
    int uniforms = 0;
    for (const auto& t : techniques::allTechniques()) {
        const std::string source = shadersOf(t.name);
        for (const auto& s : t.params) {
            if (s.gpu != ParamGpu::Uniform) continue;
            ++uniforms;
            const std::string type = s.type == ParamType::Float ? "float" : "int";
            const std::regex declaration("\\buniform\\s+" + type + "\\s+" + paramGpuName(s) +
                                         "\\b");
            EXPECT_TRUE(std::regex_search(source, declaration))
                << t.name << "." << s.key << ": no `uniform " << type << " " << paramGpuName(s)
                << "` in its shaders";
            EXPECT_TRUE(s.type != ParamType::String) << t.name << "." << s.key;
        }
    }
    EXPECT_GT(uniforms, 10);
}

TEST(GpuParams, DefineParametersAreReadByTheShaders) {
    int defines = 0;
    for (const auto& t : techniques::allTechniques()) {
        const std::string source = shadersOf(t.name);
        for (const auto& s : t.params) {
            if (s.gpu != ParamGpu::Define) continue;
            ++defines;
            const std::regex use("#\\s*(if|ifndef|ifdef|elif)\\b[^\\n]*\\b" + paramGpuName(s) +
                                 "\\b");
            EXPECT_TRUE(std::regex_search(source, use))
                << t.name << "." << s.key << ": no shader tests " << paramGpuName(s);
            EXPECT_TRUE(s.type == ParamType::Int || s.type == ParamType::Bool ||
                        s.type == ParamType::Enum)
                << t.name << "." << s.key;
        }
    }
    EXPECT_GT(defines, 5);
}

TEST(GpuParams, DefinesCarryTheValues) {
    const auto* bitmask = techniques::findTechnique("bitmask");
    ASSERT_NE(bitmask, nullptr);
    const Params p = resolveParams(
        bitmask->params,
        {{"name", "bitmask"}, {"accel", "mssm"}, {"gap_fill", false}, {"layers", 1}}, "test");
    const gl::Defines defines = gl::paramDefines(bitmask->params, p);
    const gl::Defines expected = {{"ACCEL", "1"}, {"GAP_FILL", "0"}, {"LAYERS", "1"}};
    EXPECT_EQ(defines, expected);
}

// Every `binding = X` of every shader names a constant of a bindings header.
TEST(Bindings, ShadersUseNamedBindingPoints) {
    const std::regex literal(R"(binding\s*=\s*[0-9])");
    for (std::string_view name : gl::embeddedShaderNames())
        EXPECT_FALSE(std::regex_search(gl::shaderSource(name), literal))
            << "glsl/" << name << ": a literal binding point (name it in a bindings.glsl)";
}

// The host binds the same names: no literal texture, image or buffer unit under renderer/.
TEST(Bindings, HostUsesNamedBindingPoints) {
    const std::regex literal(
        R"(glBind(TextureUnit|ImageTexture|Sampler)\(\s*[0-9]|glBindBufferBase\(\s*\w+,\s*[0-9])");
    int files = 0;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(
             std::filesystem::path(PENUMBRA_SOURCE_DIR) / "renderer")) {
        if (entry.path().extension() != ".cpp" && entry.path().extension() != ".h") continue;
        ++files;
        EXPECT_FALSE(std::regex_search(readFile(entry.path()), literal))
            << entry.path() << ": a literal binding point";
    }
    EXPECT_GT(files, 50);
}

// What the shaders were built with (the embedded headers) is what the host was compiled with.
TEST(Bindings, EmbeddedHeadersMatchTheHosts) {
    const std::regex define(R"(#define\s+([A-Z0-9_]+)\s+([0-9]+))");
    std::map<std::string, std::string> embedded;
    int headers = 0;
    for (std::string_view name : gl::embeddedShaderNames()) {
        if (!name.ends_with("/bindings.glsl")) continue;
        ++headers;
        const std::string text = gl::shaderSource(name);
        EXPECT_EQ(text, readFile(std::filesystem::path(PENUMBRA_SOURCE_DIR) / "glsl" / name))
            << name;
        for (std::sregex_iterator it(text.begin(), text.end(), define), end; it != end; ++it)
            EXPECT_TRUE(embedded.emplace((*it)[1], (*it)[2]).second)
                << (*it)[1] << " is defined by two bindings headers";
    }
    EXPECT_EQ(headers, 5);  // common, adaptive, bitmask, css, ssm
    EXPECT_EQ(embedded.at("BINDING_LIGHTS"), std::to_string(passes::kBindingLights));
    EXPECT_EQ(embedded.at("BINDING_CASTER_FLAGS"), std::to_string(passes::kBindingCasterFlags));
    EXPECT_EQ(embedded.at("MAX_SAMPLE_LOOKUPS"), std::to_string(passes::kMaxSampleLookups));
    EXPECT_EQ(embedded.at("UNIT_SHADE_VISIBILITY"), std::to_string(UNIT_SHADE_VISIBILITY));
}

// Every texture-sized map parameter named map_size is checked against GL_MAX_TEXTURE_SIZE
// before a render (the generic check asks the table, it does not look for the key).
TEST(GpuParams, MapSizesAreLimitedByTheTextureSize) {
    int limited = 0;
    for (const auto& t : techniques::allTechniques())
        for (const auto& s : t.params) {
            // Every square map a technique allocates: the memory budget no longer checks any
            // key by name against GL.
            if (s.key == "map_size" || s.key == "ssm_size" || s.key == "ysm_size") {
                EXPECT_EQ(s.limited_by, GlLimit::MaxTextureSize) << t.name << "." << s.key;
            }
            if (s.limited_by != GlLimit::None) {
                ++limited;
                EXPECT_EQ(s.type, ParamType::Int) << t.name << "." << s.key;
            }
        }
    EXPECT_EQ(limited, 8);  // map_size of every technique but exact, ssm_size, ysm_size
}
