// The render targets of `ssm`: see targets.h.
#include "renderer/techniques/ssm/targets.h"

#include <algorithm>

namespace penumbra::techniques::ssm {

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
                                     passes::Boxes receivers) {
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
