// The GL test environment: see gl_test_env.h.
#include "gl_test_env.h"

#include <algorithm>
#include <cmath>

#include "renderer/core/light_geometry.h"
#include "renderer/gl/debug.h"
#include "renderer/gl/program.h"
#include "renderer/techniques/technique.h"

// Under AddressSanitizer, leak checking is off for the GL tests: Mesa's drivers keep
// process-lifetime allocations whose stacks cannot be unwound (the unit tests keep it on).
extern "C" const char* __asan_default_options() {
    return "detect_leaks=0";
}

namespace penumbra::testing {
namespace {

std::unique_ptr<gl::Context>& context() {
    static std::unique_ptr<gl::Context> ctx;
    return ctx;
}

}  // namespace

const gl::ContextInfo& glInfo() {
    if (!context()) {
        context() = gl::Context::create({});
        gl::enableDebugOutput(false);
        gl::setStrictUniforms(true);  // a uniform no shader declares fails the test
    }
    return context()->info();
}

namespace {
output::Image render(const std::string& name, const std::vector<scene::Override>& overrides,
                     int frame, nlohmann::json* stats,
                     const std::function<void(frame::FrameRenderer&)>& configure) {
    auto source = scene::SceneSource::load(
        std::string(PENUMBRA_SOURCE_DIR) + "/tests/data/gl/" + name, overrides);
    scene::Scene s = source.at(frame);
    const auto* technique = techniques::findTechnique(s.technique.value("name", "hard"));
    if (!technique) throw std::runtime_error("unknown technique in " + name);
    Params params = resolveParams(technique->params, s.technique, name + ": technique");
    // renderFrame checks that no GL error was raised by the render.
    frame::RenderedFrame r = frame::renderFrame(glInfo(), s, *technique, params, {}, configure);
    if (stats) *stats = std::move(r.stats);
    return std::move(r.image);
}
}  // namespace

output::Image renderScene(const std::string& name, const std::vector<scene::Override>& overrides,
                          int frame, nlohmann::json* stats) {
    return render(name, overrides, frame, stats, nullptr);
}

output::Image renderSceneWith(const std::string& name,
                              const std::vector<scene::Override>& overrides,
                              const std::function<void(frame::FrameRenderer&)>& configure) {
    return render(name, overrides, 0, nullptr, configure);
}

double sumOverObject(const output::Image& img, const std::string& name, int id,
                     const output::Image* ids) {
    const auto& v = channel(img, name);
    const auto& of = channel(ids ? *ids : img, "id");
    double sum = 0;
    for (size_t i = 0; i < v.size(); ++i)
        if (of[i] == float(id)) sum += v[i];
    return sum;
}

double pixelIrradiance(const scene::RectLight& light, const output::Image& img, size_t i) {
    const auto c = light.corners();
    const std::array<glm::dvec3, 4> corners = {glm::dvec3(c[0]), glm::dvec3(c[1]), glm::dvec3(c[2]),
                                               glm::dvec3(c[3])};
    const glm::dvec3 p(channel(img, "P.X")[i], channel(img, "P.Y")[i], channel(img, "P.Z")[i]);
    const glm::dvec3 n = glm::normalize(
        glm::dvec3(channel(img, "N.X")[i], channel(img, "N.Y")[i], channel(img, "N.Z")[i]));
    return rectLightIrradiance(corners, glm::dvec3(light.forward()), p, n);
}

double closedFormShadowMae(const output::Image& img, double light_half, long min_pixels) {
    const auto& vis = channel(img, "visibility");
    const auto& id = channel(img, "id");
    const auto& px = channel(img, "P.X");
    const auto& py = channel(img, "P.Y");
    const auto& pz = channel(img, "P.Z");
    double sum = 0;
    long n = 0;
    for (size_t i = 0; i < vis.size(); ++i) {
        if (id[i] != 0.0f) continue;  // floor only
        const double expected = parallelSquareOccluderVisibility(
            {0, 3, 0}, light_half, {0.2, 1.5, 0.1}, 0.4, {px[i], py[i], pz[i]});
        if (expected >= 0.999 && vis[i] >= 0.999f) continue;
        sum += std::fabs(expected - vis[i]);
        ++n;
    }
    EXPECT_GT(n, min_pixels) << "the shadow should cover a good part of the floor";
    return n ? sum / static_cast<double>(n) : 1.0;
}

namespace {
// Mean |a - truth| over pixels where either is below 0.999 and, with ID, whose object is
// OBJECT.
double meanShadowDifference(const std::vector<float>& a, const std::vector<float>& truth,
                            const std::vector<float>* id, int object, long min_pixels) {
    double sum = 0;
    long n = 0;
    for (size_t i = 0; i < a.size(); ++i) {
        if ((id && (*id)[i] != float(object)) || (a[i] >= 0.999f && truth[i] >= 0.999f)) continue;
        sum += std::fabs(double(a[i]) - double(truth[i]));
        ++n;
    }
    EXPECT_GT(n, min_pixels) << "the shadow should cover a good part of "
                             << (id ? "object " + std::to_string(object) : "the image");
    return n ? sum / static_cast<double>(n) : 1.0;
}
}  // namespace

double floorShadowMae(const output::Image& ref, const output::Image& test, long min_pixels) {
    return objectShadowMae(ref, test, 0, min_pixels);
}

double objectShadowMae(const output::Image& ref, const output::Image& test, int object,
                       long min_pixels) {
    return meanShadowDifference(channel(test, "visibility"), channel(ref, "visibility"),
                                &channel(test, "id"), object, min_pixels);
}

double shadowRegionMae(const std::vector<float>& a, const std::vector<float>& truth,
                       long min_pixels) {
    return meanShadowDifference(a, truth, nullptr, 0, min_pixels);
}

double maxAbsDifference(const std::vector<float>& a, const std::vector<float>& b) {
    if (a.size() != b.size()) throw std::runtime_error("maxAbsDifference: sizes differ");
    double max = 0;
    for (size_t i = 0; i < a.size(); ++i) max = std::max(max, double(std::fabs(a[i] - b[i])));
    return max;
}

const std::vector<float>& channel(const output::Image& image, const std::string& name) {
    const auto* c = image.find(name);
    if (!c) throw std::runtime_error("no channel " + name);
    return c->pixels;
}

gl::Program linkTestProgram(const std::string& label,
                            std::initializer_list<std::pair<GLenum, std::string>> stages) {
    gl::Program program(glCreateProgram(), label);
    GLint ok = 0;
    for (const auto& [stage, source] : stages) {
        const GLuint shader = glCreateShader(stage);
        const char* text = source.c_str();
        glShaderSource(shader, 1, &text, nullptr);
        glCompileShader(shader);
        glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
        EXPECT_TRUE(ok) << label << ": a stage did not compile";
        glAttachShader(program.id(), shader);
        glDeleteShader(shader);  // freed with the program
    }
    glLinkProgram(program.id());
    glGetProgramiv(program.id(), GL_LINK_STATUS, &ok);
    EXPECT_TRUE(ok) << label << ": did not link";
    return program;
}

}  // namespace penumbra::testing
