// Importance sampling of a scene's equirectangular environment for `exact`: directions drawn
// in proportion to the map's luminance (per block of texels), their solid-angle densities, and
// the radiance a direction sees, all in world space (the map turned by rotation_y).
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "renderer/scene/scene.h"

namespace penumbra::techniques::exact {

class EnvironmentSampler {
public:
    // At most MAX_BLOCKS_X x MAX_BLOCKS_X / 2 blocks of texels carry the distribution.
    explicit EnvironmentSampler(const scene::Environment& env, int max_blocks_x = 512);
    // Whether the map has any energy (otherwise nothing may be sampled).
    bool empty() const { return !(total_ > 0); }
    // A world direction from two uniform numbers in [0, 1).
    glm::vec3 sample(float u1, float u2) const;
    // The solid-angle density of sample() at world direction DIR (unit).
    float pdf(const glm::vec3& dir) const;
    // Radiance (intensity x the texel's colour) seen along world direction DIR (unit).
    glm::vec3 radiance(const glm::vec3& dir) const;

private:
    glm::vec3 toMap(const glm::vec3& world) const;
    glm::vec3 toWorld(const glm::vec3& map) const;

    const scene::EnvironmentImage& image_;
    float intensity_, cos_r_, sin_r_;
    int bx_, by_;                  // blocks across and down
    std::vector<double> rows_;     // cumulative energy of the rows of blocks (by_)
    std::vector<double> columns_;  // per row, cumulative energy of its blocks (by_ x bx_)
    std::vector<float> density_;   // per block: probability / solid angle
    double total_ = 0;
};

}  // namespace penumbra::techniques::exact
