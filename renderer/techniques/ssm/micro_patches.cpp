// The paper's CPU path: see micro_patches.h.
#include "renderer/techniques/ssm/micro_patches.h"

namespace penumbra::techniques::ssm {

void readMicroPatches(const gl::Texture& depth, int map_size, const passes::LightWindow& window,
                      float empty, std::vector<float>& scratch, std::vector<MicroPatch>& patches) {
    const size_t n = static_cast<size_t>(map_size) * static_cast<size_t>(map_size);
    scratch.resize(n);
    glGetTextureImage(depth.id(), 0, GL_DEPTH_COMPONENT, GL_FLOAT,
                      static_cast<GLsizei>(n * sizeof(float)), scratch.data());
    patches.clear();
    for (int j = 0; j < map_size; ++j)
        for (int i = 0; i < map_size; ++i) {
            const float d = scratch[static_cast<size_t>(j) * static_cast<size_t>(map_size) +
                                    static_cast<size_t>(i)];
            if (d == empty) continue;
            const float z = window.near + d * (window.far - window.near);
            patches.push_back({static_cast<std::uint32_t>(j * map_size + i), z});
        }
}

}  // namespace penumbra::techniques::ssm
