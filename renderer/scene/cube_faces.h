// Equirectangular environment maps as six cube faces of energy: the direction convention of
// PRODUCT.md's `environment` (shared by fitting and shading), texel solid angles, and the
// resampling of an EnvironmentImage into faces of radiance x solid angle per texel.
#pragma once

#include <array>
#include <vector>

#include <glm/glm.hpp>

#include "renderer/scene/scene.h"

namespace penumbra::scene {

// Image (u, v) in [0,1]^2 (u left to right, v top to bottom) <-> world direction: v = 0 is +Y
// (up), the image centre (u = 0.5, v = 0.5) looks along -Z, u = 0.75 along +X.
glm::vec3 equirectDirection(float u, float v);
glm::vec2 equirectCoordinates(const glm::vec3& direction);

// Cube faces in GL order +X, -X, +Y, -Y, +Z, -Z; face coordinates a (right) and b (down) in
// [-1, 1] as in GL cube maps.
constexpr std::array<const char*, 6> kCubeFaceNames = {"+X", "-X", "+Y", "-Y", "+Z", "-Z"};
glm::vec3 cubeDirection(int face, float a, float b);  // not normalised
// Solid angle of texel (i, j) of an N x N face.
double cubeTexelSolidAngle(int n, int i, int j);

struct CubeFaces {
    int size = 0;                                  // N: texels per face side
    std::array<std::vector<glm::vec3>, 6> energy;  // RGB radiance x solid angle, row-major
    double totalLuminance() const;
};

// Resamples IMAGE (scaled by INTENSITY) into faces of SIZE^2 texels, each the mean of a few
// bilinear samples of the map inside it (enough that no map texel is skipped).
CubeFaces toCubeFaces(const EnvironmentImage& image, int size, float intensity = 1.0f);

// Rec. 709 luminance of linear RGB.
inline double luminance(const glm::vec3& c) {
    return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b;
}

}  // namespace penumbra::scene
