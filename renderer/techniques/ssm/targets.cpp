// The render targets of `ssm`: see targets.h.
#include "renderer/techniques/ssm/targets.h"
#include "glsl/techniques/ssm/bindings.glsl"

#include <algorithm>

namespace penumbra::techniques::ssm {

ReceiverLayers::ReceiverLayers(int size_, int layers_, const char* label)
    : size(size_),
      layers(layers_),
      depth(gl::createTexture2DArray(GL_DEPTH_COMPONENT32F, size_, size_, layers_, label)),
      ids(gl::createTexture2DArray(GL_R32I, size_, size_, layers_, label)),
      scratch(size_, label, true),
      resolve(gl::buildProgram("ssm farthest receiver layer",
                               {"passes/fullscreen.vert", "techniques/ssm/peel_resolve.frag"})),
      last_fbo(gl::createFramebuffer(label)) {
    glNamedFramebufferTextureLayer(last_fbo.id(), GL_DEPTH_ATTACHMENT, depth.id(), 0, layers - 1);
    glNamedFramebufferDrawBuffer(last_fbo.id(), GL_NONE);
    passes::checkFramebuffer(last_fbo, label);
}

int ReceiverLayers::render(const passes::GpuScene& scene, const passes::LightDepthPass& peel,
                           passes::GpuScene::Filter filter, const scene::RectLight& light,
                           const passes::LightDepthView& view, float gap) const {
    const gl::Program& program = peel.program();
    glUseProgram(program.id());
    gl::setUniform(program, "u_peel_gap", gap);
    // Each layer is drawn into the scratch map, reading the layer before from the array, and
    // then copied into the array: a layer is never sampled while it is drawn.
    glBindTextureUnit(SSM_UNIT_PEEL_PREVIOUS, depth.id());
    const gl::Query any = gl::createQuery(GL_ANY_SAMPLES_PASSED, "ssm receiver layer");
    int used = 0;
    for (int k = 0; k < layers; ++k) {
        glUseProgram(program.id());
        gl::setUniform(program, "u_layer", k);
        const bool farthest = k > 0 && k == layers - 1;
        glBeginQuery(GL_ANY_SAMPLES_PASSED, any.id());
        scratch.render(scene, peel, filter, light, view, farthest);
        glEndQuery(GL_ANY_SAMPLES_PASSED);
        if (farthest) {
            // Cleared to 0 for the greater test: written with 1 for "none" instead.
            glBindFramebuffer(GL_FRAMEBUFFER, last_fbo.id());
            glViewport(0, 0, size, size);
            glEnable(GL_DEPTH_TEST);
            glDepthFunc(GL_ALWAYS);
            glDepthMask(GL_TRUE);
            glUseProgram(resolve.id());
            glBindTextureUnit(SSM_UNIT_RESOLVE_DEPTH, scratch.depth.id());
            glBindTextureUnit(SSM_UNIT_RESOLVE_IDS, scratch.ids.id());
            fullscreen.draw();
            glDepthFunc(GL_LESS);
            glDisable(GL_DEPTH_TEST);
            glBindFramebuffer(GL_FRAMEBUFFER, 0);
            glBindTextureUnit(SSM_UNIT_PEEL_PREVIOUS, depth.id());
        } else {
            glCopyImageSubData(scratch.depth.id(), GL_TEXTURE_2D, 0, 0, 0, 0, depth.id(),
                               GL_TEXTURE_2D_ARRAY, 0, 0, 0, k, size, size, 1);
        }
        glCopyImageSubData(scratch.ids.id(), GL_TEXTURE_2D, 0, 0, 0, 0, ids.id(),
                           GL_TEXTURE_2D_ARRAY, 0, 0, 0, k, size, size, 1);
        GLuint passed = 0;
        glGetQueryObjectuiv(any.id(), GL_QUERY_RESULT, &passed);
        if (!passed) {
            // Empty from here on: the deeper layers keep "none" (1) for the lookups.
            const float none = 1.0f;
            const GLint no_id = -1;
            if (k + 1 < layers) {
                glClearTexSubImage(depth.id(), 0, 0, 0, k + 1, size, size, layers - k - 1,
                                   GL_DEPTH_COMPONENT, GL_FLOAT, &none);
                glClearTexSubImage(ids.id(), 0, 0, 0, k + 1, size, size, layers - k - 1,
                                   GL_RED_INTEGER, GL_INT, &no_id);
            }
            break;
        }
        used = k + 1;
    }
    return used;
}

SoftShadowTarget::SoftShadowTarget(int size, int layers, GLenum format, const char* label)
    : occlusion(gl::createTexture2DArray(format, size, size, layers, label)) {
    glTextureParameteri(occlusion.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(occlusion.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    for (int k = 0; k < layers; ++k) {
        fbos.push_back(gl::createFramebuffer(label));
        glNamedFramebufferTextureLayer(fbos.back().id(), GL_COLOR_ATTACHMENT0, occlusion.id(), 0,
                                       k);
        passes::checkFramebuffer(fbos.back(), label);
    }
}

passes::LightWindow withNearMargin(passes::LightWindow w) {
    if (w.empty()) return w;
    w.near = std::max(w.near * (1.0f - 1e-4f) - 1e-5f, w.far * 1e-4f);
    return w;
}

passes::LightWindow softShadowWindow(const scene::RectLight& light,
                                     const passes::LightWindow& occluders,
                                     const passes::Bounds& receivers) {
    passes::LightWindow r = withNearMargin(passes::windowOf(light, receivers));
    if (r.empty() || occluders.empty()) return {};
    const float k = std::max(1.0f / occluders.near - 1.0f / r.far, 0.0f);
    const glm::vec2 grow = 0.5f * light.size * k;
    const glm::vec2 lo = glm::max(occluders.lo - grow, r.lo);
    const glm::vec2 hi = glm::min(occluders.lo + occluders.size + grow, r.lo + r.size);
    r.lo = lo, r.size = glm::max(hi - lo, glm::vec2(0.0f));
    return r;
}

}  // namespace penumbra::techniques::ssm
