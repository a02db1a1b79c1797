// The paper's CPU path: see micro_patches.h.
#include "renderer/techniques/ssm/micro_patches.h"

namespace penumbra::techniques::ssm {

void readMicroPatches(const gl::Texture& source, bool merged, int map_size,
                      const passes::LightWindow& window, float empty, std::vector<float>& scratch,
                      std::vector<MicroPatch>& patches) {
    const size_t n = static_cast<size_t>(map_size) * static_cast<size_t>(map_size);
    const size_t channels = merged ? 4 : 1;
    scratch.resize(n * channels);
    glGetTextureImage(source.id(), 0, merged ? GL_RGBA : GL_DEPTH_COMPONENT, GL_FLOAT,
                      static_cast<GLsizei>(n * channels * sizeof(float)), scratch.data());
    patches.clear();
    for (size_t t = 0; t < n; ++t) {
        const float d = scratch[t * channels];
        if (d == empty) continue;
        const auto level = merged ? static_cast<std::uint32_t>(scratch[t * channels + 1]) : 0u;
        const float near = merged ? scratch[t * channels + 2] : d;
        const float z = window.near + d * (window.far - window.near);
        const float z_near = window.near + near * (window.far - window.near);
        patches.push_back({static_cast<std::uint32_t>(t) | (level << kLevelShift), z, z_near});
    }
}

}  // namespace penumbra::techniques::ssm
