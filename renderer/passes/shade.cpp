// The shade pass: see shade.h.
#include "renderer/passes/shade.h"

#include <cstddef>
#include <string>

#include "renderer/core/error.h"
#include "renderer/passes/bindings.h"

namespace penumbra::passes {
namespace {
struct GpuLight {  // std430 mirror of GpuLight in glsl/passes/shading.glsl
    glm::vec4 corners[4];
    glm::vec4 forward;
    glm::vec4 radiance;
};
static_assert(sizeof(GpuLight) == GPU_LIGHT_SIZE, "GpuLight: std430 size");
static_assert(offsetof(GpuLight, forward) == 64 && offsetof(GpuLight, radiance) == 80,
              "GpuLight: std430 offsets (vec4 members, 16-byte aligned)");
}  // namespace

Shade::Shade(int width, int height, int samples, const gl::Buffer& caster_flags)
    : width_(width),
      height_(height),
      samples_(samples),
      caster_flags_(caster_flags),
      beauty_(gl::createTexture2D(GL_RGBA32F, width, height, "beauty")),
      visibility_(gl::createTexture2D(GL_R32F, width, height, "visibility")),
      fbo_(gl::createFramebuffer("shade")) {
    glNamedFramebufferTexture(fbo_.id(), GL_COLOR_ATTACHMENT0, beauty_.id(), 0);
    glNamedFramebufferTexture(fbo_.id(), GL_COLOR_ATTACHMENT1, visibility_.id(), 0);
    const GLenum bufs[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    glNamedFramebufferDrawBuffers(fbo_.id(), 2, bufs);
    if (samples > 1) {
        stencil_ = gl::createTexture2D(GL_STENCIL_INDEX8, width, height, "shade msaa pixels");
        glNamedFramebufferTexture(fbo_.id(), GL_STENCIL_ATTACHMENT, stencil_.id(), 0);
        classify_ = gl::buildProgram("msaa classify",
                                     {"passes/fullscreen.vert", "passes/msaa_classify.frag"});
        pixels_ = gl::createQuery(GL_SAMPLES_PASSED, "shade msaa pixels");
    }
    if (glCheckNamedFramebufferStatus(fbo_.id(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw RuntimeError("shade: framebuffer incomplete");
}

const gl::Program& Shade::programFor(std::map<int, gl::Program>& cache, int count,
                                     const char* label, const char* fragment) {
    const int key = count <= kCompiledLights ? count : -1;
    auto it = cache.find(key);
    if (it != cache.end()) return it->second;
    gl::Defines defines;
    if (key >= 0) defines.emplace_back("LIGHT_COUNT", std::to_string(key));
    return cache
        .emplace(key, gl::buildProgram(label, {"passes/fullscreen.vert", fragment}, defines))
        .first->second;
}

void uploadGpuLights(gl::DynamicBuffer& buffer, const std::vector<scene::RectLight>& lights) {
    std::vector<GpuLight> data;
    for (const auto& l : lights) {
        GpuLight g;
        auto c = l.corners();
        for (int i = 0; i < 4; ++i) g.corners[i] = glm::vec4(c[static_cast<size_t>(i)], 1.0f);
        g.forward = glm::vec4(l.forward(), 0.0f);
        glm::vec3 r = l.radiance();
        g.radiance = glm::vec4(r, 0.2126f * r.x + 0.7152f * r.y + 0.0722f * r.z);
        data.push_back(g);
    }
    buffer.upload(std::span<const GpuLight>(data), GL_SHADER_STORAGE_BUFFER, kBindingLights);
}

void Shade::render(const GBuffer& gbuffer, const gl::Texture& visibility_layers,
                   const std::vector<scene::RectLight>& lights, int env_layer) {
    uploadGpuLights(lights_, lights);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
    glViewport(0, 0, width_, height_);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    const int count = static_cast<int>(lights.size());
    const gl::Program& program = programFor(programs_, count, "shade", "passes/shade.frag");
    glUseProgram(program.id());
    glBindTextureUnit(UNIT_SHADE_POSITION, gbuffer.position().id());
    glBindTextureUnit(UNIT_SHADE_NORMAL, gbuffer.normal().id());
    glBindTextureUnit(UNIT_SHADE_ALBEDO, gbuffer.albedo().id());
    glBindTextureUnit(UNIT_SHADE_VISIBILITY, visibility_layers.id());
    glBindTextureUnit(UNIT_SHADE_ID, gbuffer.id().id());
    gbuffer.bindGeometricNormal();
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kBindingCasterFlags, caster_flags_.id());
    gl::setUniform(program, "u_light_count", count);
    gl::setUniform(program, "u_env_layer", env_layer);
    fullscreen_.draw();
    glUseProgram(0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void Shade::renderSamples(const GBuffer& gbuffer, const SampleGBuffer& samples,
                          const gl::Texture& visibility_layers,
                          const std::vector<scene::RectLight>& lights, int env_layer) {
    if (samples.samples() != samples_)
        throw RuntimeError("shade: built for " + std::to_string(samples_) + " samples, given " +
                           std::to_string(samples.samples()));
    uploadGpuLights(lights_, lights);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
    glViewport(0, 0, width_, height_);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glBindTextureUnit(UNIT_SHADE_POSITION, gbuffer.position().id());
    glBindTextureUnit(UNIT_SHADE_NORMAL, gbuffer.normal().id());
    glBindTextureUnit(UNIT_SHADE_ALBEDO, gbuffer.albedo().id());
    glBindTextureUnit(UNIT_SHADE_VISIBILITY, visibility_layers.id());
    glBindTextureUnit(UNIT_SHADE_ID, gbuffer.id().id());
    glBindTextureUnit(UNIT_SHADE_SAMPLE_POSITION, samples.position().id());
    glBindTextureUnit(UNIT_SHADE_SAMPLE_NORMAL, samples.normal().id());
    glBindTextureUnit(UNIT_SHADE_SAMPLE_ALBEDO, samples.albedo().id());
    glBindTextureUnit(UNIT_SHADE_SAMPLE_ID, samples.id().id());
    gbuffer.bindGeometricNormal();
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kBindingCasterFlags, caster_flags_.id());
    // 1. Stencil 1 where a sample differs from the representative (colour untouched).
    const GLint zero = 0;
    glClearNamedFramebufferiv(fbo_.id(), GL_STENCIL, 0, &zero);
    glEnable(GL_STENCIL_TEST);
    glStencilMask(0xff);
    glStencilFunc(GL_ALWAYS, 1, 0xff);
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glUseProgram(classify_.id());
    gl::setUniform(classify_, "u_samples", samples_);
    fullscreen_.draw();
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    // 2. Those pixels shaded per sample and resolved, over render()'s result. The stencil test
    // runs before the shader, so the other pixels cost nothing.
    glStencilFunc(GL_EQUAL, 1, 0xff);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    const auto& p = programFor(samples_programs_, static_cast<int>(lights.size()), "shade samples",
                               "passes/shade_samples.frag");
    glUseProgram(p.id());
    gl::setUniform(p, "u_light_count", static_cast<int>(lights.size()));
    gl::setUniform(p, "u_env_layer", env_layer);
    gl::setUniform(p, "u_samples", samples_);
    gl::setUniform(p, "u_guide", guide_ == SampleGuide::Depth ? 1 : 0);
    glBeginQuery(GL_SAMPLES_PASSED, pixels_.id());
    fullscreen_.draw();
    glEndQuery(GL_SAMPLES_PASSED);
    glUseProgram(0);
    glDisable(GL_STENCIL_TEST);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

double Shade::samplePixels() const {
    if (!pixels_) return 0.0;
    GLuint64 n = 0;
    glGetQueryObjectui64v(pixels_.id(), GL_QUERY_RESULT, &n);
    return static_cast<double>(n);
}

}  // namespace penumbra::passes
