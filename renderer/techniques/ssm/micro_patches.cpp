// The paper's CPU path: see micro_patches.h.
#include "renderer/techniques/ssm/micro_patches.h"

namespace penumbra::techniques::ssm {

ClassCounts readMicroPatches(const gl::Texture& source, const gl::Texture* slopes, int map_size,
                             const passes::LightWindow& window, float empty,
                             std::vector<float>& scratch, std::vector<MicroPatch>& patches) {
    const size_t n = static_cast<size_t>(map_size) * static_cast<size_t>(map_size);
    const bool merged = slopes != nullptr;
    const size_t channels = merged ? 4 : 1;
    scratch.resize(n * (channels + (merged ? 2 : 0)));
    glGetTextureImage(source.id(), 0, merged ? GL_RGBA : GL_DEPTH_COMPONENT, GL_FLOAT,
                      static_cast<GLsizei>(n * channels * sizeof(float)), scratch.data());
    const float* slope = scratch.data() + n * channels;
    if (merged)
        glGetTextureImage(slopes->id(), 0, GL_RG, GL_FLOAT,
                          static_cast<GLsizei>(n * 2 * sizeof(float)),
                          scratch.data() + n * channels);
    patches.clear();
    for (size_t t = 0; t < n; ++t) {
        const float d = scratch[t * channels];
        if (d == empty) continue;
        const auto level = merged ? static_cast<std::uint32_t>(scratch[t * channels + 1]) : 0u;
        const float near = merged ? scratch[t * channels + 2] : d;
        const float z = window.near + d * (window.far - window.near);
        const float z_near = window.near + near * (window.far - window.near);
        const float sx = merged ? slope[2 * t] : 0.0f, sy = merged ? slope[2 * t + 1] : 0.0f;
        patches.push_back(
            {static_cast<std::uint32_t>(t) | (level << kLevelShift), z, z_near, sx, sy});
    }
    // Class by class, each in texel order: every patch at its class's next slot.
    ClassCounts counts{};
    for (const auto& p : patches) ++counts[size_t(patchClass(p))];
    ClassCounts next{};
    for (size_t c = 1; c < next.size(); ++c) next[c] = next[c - 1] + counts[c - 1];
    std::vector<MicroPatch> listed(patches.size());
    for (const auto& p : patches) listed[next[size_t(patchClass(p))]++] = p;
    patches.swap(listed);
    return counts;
}

}  // namespace penumbra::techniques::ssm
