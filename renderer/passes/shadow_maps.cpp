// Light-sample shadow maps: see shadow_maps.h.
#include "renderer/passes/shadow_maps.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "renderer/core/error.h"
#include "renderer/passes/bindings.h"
#include "renderer/passes/light_windows.h"

namespace penumbra::passes {
SampleView makeSampleView(const scene::RectLight& light, const glm::vec3& point, Boxes casters,
                          float weight, int map_size) {
    const glm::vec3 f = light.forward(), r = light.right(), u = light.upAxis();
    const std::vector<glm::vec3> points = visibleVertices(casters, light, point);
    float zmin = 1e30f, zmax = 0.0f;
    for (const auto& p : points) zmin = std::min(zmin, p.z), zmax = std::max(zmax, p.z);
    if (zmax <= 0.0f) zmin = 0.01f, zmax = 1.0f;  // nothing in front: any frustum is empty
    // A margin on both planes: a flat caster parallel to the light lies exactly at zmin, where
    // rasterisation would clip it away.
    const float margin = 0.01f * std::max(zmax - zmin, std::fabs(zmin)) + 1e-5f;
    const float near = std::max(zmin - margin, zmax * 1e-4f);
    const float far = zmax + margin;
    float lo_x = 1e30f, hi_x = -1e30f, lo_y = 1e30f, hi_y = -1e30f;
    for (const auto& p : points) {
        const float z = std::max(p.z, near);
        lo_x = std::min(lo_x, p.x / z), hi_x = std::max(hi_x, p.x / z);
        lo_y = std::min(lo_y, p.y / z), hi_y = std::max(hi_y, p.y / z);
    }
    if (!(lo_x < hi_x)) lo_x = -1, hi_x = 1;
    if (!(lo_y < hi_y)) lo_y = -1, hi_y = 1;
    const float k = kMaxViewTan;
    lo_x = std::clamp(lo_x, -k, k), hi_x = std::clamp(hi_x, -k, k);
    lo_y = std::clamp(lo_y, -k, k), hi_y = std::clamp(hi_y, -k, k);
    // One texel of margin so casters on the edge are rasterised.
    const float mx = (hi_x - lo_x) / static_cast<float>(map_size);
    const float my = (hi_y - lo_y) / static_cast<float>(map_size);
    lo_x -= mx, hi_x += mx, lo_y -= my, hi_y += my;

    glm::mat4 view(1.0f);
    view[0][0] = r.x, view[1][0] = r.y, view[2][0] = r.z;
    view[0][1] = u.x, view[1][1] = u.y, view[2][1] = u.z;
    view[0][2] = -f.x, view[1][2] = -f.y, view[2][2] = -f.z;
    view[3][0] = -glm::dot(r, point);
    view[3][1] = -glm::dot(u, point);
    view[3][2] = glm::dot(f, point);
    // glm::frustum with the caster extent at the near plane.
    glm::mat4 proj(0.0f);
    proj[0][0] = 2.0f / (hi_x - lo_x);
    proj[1][1] = 2.0f / (hi_y - lo_y);
    proj[2][0] = (hi_x + lo_x) / (hi_x - lo_x);
    proj[2][1] = (hi_y + lo_y) / (hi_y - lo_y);
    proj[2][2] = -(far + near) / (far - near);
    proj[2][3] = -1.0f;
    proj[3][2] = -2.0f * far * near / (far - near);

    SampleView v;
    v.view_proj = proj * view;
    v.origin = glm::vec4(point, weight);
    v.forward = glm::vec4(f, near);
    v.params = glm::vec4(far, std::max(hi_x - lo_x, hi_y - lo_y) / static_cast<float>(map_size),
                         0.0f, 0.0f);
    v.light_origin = glm::vec4(glm::dot(point, r), glm::dot(point, u), glm::dot(point, f), near);
    v.frustum = glm::vec4(lo_x, lo_y, 1.0f / (hi_x - lo_x), 1.0f / (hi_y - lo_y));
    v.depth = glm::vec4(1.0f / (far - near), weight, 0.0f, 0.0f);
    return v;
}

ShadowMapBatch::ShadowMapBatch(int map_size, int layers, bool vertex_layer)
    : map_size_(map_size),
      layers_(layers),
      vertex_layer_(vertex_layer),
      depth_(gl::createTexture2DArray(GL_DEPTH_COMPONENT32F, map_size, map_size, layers,
                                      "shadow map array")),
      fbo_(gl::createFramebuffer("shadow maps")),
      program_(buildSampleDepthProgram("shadow depth", vertex_layer)) {
    glTextureParameteri(depth_.id(), GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    glTextureParameteri(depth_.id(), GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    glNamedFramebufferDrawBuffer(fbo_.id(), GL_NONE);
    glNamedFramebufferReadBuffer(fbo_.id(), GL_NONE);
    if (vertex_layer_) {
        glNamedFramebufferTexture(fbo_.id(), GL_DEPTH_ATTACHMENT, depth_.id(), 0);
        checkFramebuffer(fbo_, "shadow maps");
    }
}

void ShadowMapBatch::render(const GpuScene& scene, int view_base, int count) {
    count = std::min(count, layers_);
    beginDepthMapDraw(fbo_.id(), map_size_);
    glUseProgram(program_.id());
    const float one = 1.0f;
    if (vertex_layer_) {
        glClearNamedFramebufferfv(fbo_.id(), GL_DEPTH, 0, &one);
        gl::setUniform(program_, "u_view_base", view_base);
        scene.draw(program_, GpuScene::Filter::Casters, count);
    } else {
        for (int i = 0; i < count; ++i) {
            glNamedFramebufferTextureLayer(fbo_.id(), GL_DEPTH_ATTACHMENT, depth_.id(), 0, i);
            glClearNamedFramebufferfv(fbo_.id(), GL_DEPTH, 0, &one);
            gl::setUniform(program_, "u_view_base", view_base + i);
            scene.draw(program_, GpuScene::Filter::Casters, 1);
        }
    }
    glUseProgram(0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void ShadowMapBatch::render(const GpuScene& scene, int view_base, int count, int first_layer) {
    count = std::min(count, layers_ - first_layer);
    if (count <= 0) return;
    if (!vertex_layer_) {
        beginDepthMapDraw(fbo_.id(), map_size_);
        glUseProgram(program_.id());
        const float one = 1.0f;
        for (int i = 0; i < count; ++i) {
            glNamedFramebufferTextureLayer(fbo_.id(), GL_DEPTH_ATTACHMENT, depth_.id(), 0,
                                           first_layer + i);
            glClearNamedFramebufferfv(fbo_.id(), GL_DEPTH, 0, &one);
            gl::setUniform(program_, "u_view_base", view_base + i);
            scene.draw(program_, GpuScene::Filter::Casters, 1);
        }
        glUseProgram(0);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        return;
    }
    // A view of the layers, attached layered: gl_Layer 0.. lands on FIRST_LAYER.., and the
    // clear touches only them.
    GLuint view = 0;
    glGenTextures(1, &view);
    glTextureView(view, GL_TEXTURE_2D_ARRAY, depth_.id(), GL_DEPTH_COMPONENT32F, 0, 1,
                  GLuint(first_layer), GLuint(count));
    glNamedFramebufferTexture(fbo_.id(), GL_DEPTH_ATTACHMENT, view, 0);
    render(scene, view_base, count);
    glNamedFramebufferTexture(fbo_.id(), GL_DEPTH_ATTACHMENT, depth_.id(), 0);
    glDeleteTextures(1, &view);
}

ShadowAccumulate::ShadowAccumulate() {
    program(1);  // the default, built up front as before
}

const gl::Program& ShadowAccumulate::program(int pcf) {
    auto it = programs_.find(pcf);
    if (it != programs_.end()) return it->second;
    return programs_
        .emplace(pcf, gl::buildProgram("shadow accumulate",
                                       {"passes/fullscreen.vert", "passes/shadow_accumulate.frag"},
                                       {{"PCF", std::to_string(pcf)}}))
        .first->second;
}

void ShadowAccumulate::render(const GBuffer& gbuffer, const ShadowMapBatch& batch, int view_base,
                              int count, const scene::RectLight& light, const ShadowTestSettings& s,
                              const gl::Buffer& caster_flags) {
    const gl::Program& shader = program(s.pcf);
    glUseProgram(shader.id());
    glBindTextureUnit(UNIT_ACCUMULATE_POSITION, gbuffer.position().id());
    glBindTextureUnit(UNIT_ACCUMULATE_NORMAL, gbuffer.normal().id());
    glBindTextureUnit(UNIT_ACCUMULATE_MAPS, batch.depth().id());
    glBindTextureUnit(UNIT_ACCUMULATE_ID, gbuffer.id().id());
    gbuffer.bindGeometricNormal();
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kBindingCasterFlags, caster_flags.id());
    gl::setUniform(shader, "u_view_base", view_base);
    gl::setUniform(shader, "u_count", std::min(count, batch.layers()));
    gl::setUniform(shader, "u_normal_offset", s.normal_offset);
    gl::setUniform(shader, "u_depth_bias", s.depth_bias);
    setLightFrameUniforms(shader, light);
    glDisable(GL_DEPTH_TEST);
    fullscreen_.draw();
    glUseProgram(0);
}

void SampleViewBuffer::upload(std::span<const SampleView> views) {
    if (views.size() > static_cast<size_t>(kMaxSampleLookups))
        throw RuntimeError("sample views: " + std::to_string(views.size()) + " views, at most " +
                           std::to_string(kMaxSampleLookups) + " per light");
    views_.upload(views, GL_SHADER_STORAGE_BUFFER, kBindingSampleViews);
    staging_.clear();
    for (const auto& v : views) {
        staging_.push_back(v.light_origin);
        staging_.push_back(v.frustum);
        staging_.push_back(v.depth);
    }
    // The uniform block is declared at its full size, so the buffer always has that size.
    lookups_.upload(std::span<const glm::vec4>(staging_), GL_UNIFORM_BUFFER, kBindingSampleLookups,
                    3 * sizeof(glm::vec4) * static_cast<size_t>(kMaxSampleLookups));
}

}  // namespace penumbra::passes
