// One pixel's shadow rays for `exact`: the G-buffer, the casters and the settings they need, and
// the two estimators (a rect light's N x N points, the environment's importance samples).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "renderer/techniques/exact/environment_sampler.h"
#include "renderer/techniques/exact/ray_scene.h"

namespace penumbra::techniques::exact {

// A rect light as the rays see it: a corner, its two edges and the direction it faces.
struct AreaLight {
    glm::vec3 corner, edge_x, edge_y, forward;
};

struct PixelTracer {
    const std::vector<float>& position;   // the G-buffer's RGBA positions (a = 0: background)
    const std::vector<float>& normal;     // and normals (shading)
    const std::vector<float>& geometric;  // and facet normals (the triangles' planes)
    // Per pixel, whether its object casts: a ray from such a surface toward the side its facet
    // faces away from (the far side of the tangent plane of the side seen) crosses the surface
    // itself at its start, open sheet or closed, and counts as blocked without being cast.
    const std::vector<std::uint8_t>& casts;
    const RayScene& rays;
    const EnvironmentSampler* environment;  // null without an environment layer
    bool jitter;
    std::uint32_t seed;
    int env_samples;

    // One pixel's rays: OUT gets (unblocked share, sum c lit, sum c, 1), c = cos cos / r^2 of
    // the sample (0 below the receiver's horizon and behind the light). Returns rays cast.
    std::uint64_t tracePixel(const AreaLight& light, int n, std::size_t pix, float tnear,
                             std::vector<float>& out) const;
    // The environment at one pixel: OUT gets (shadowed irradiance rgb, unshadowed luminance
    // irradiance) from env_samples rays. Returns rays cast.
    std::uint64_t traceEnvironment(std::size_t pix, float tnear, std::vector<float>& out) const;

    glm::vec3 positionAt(std::size_t pix) const;
    // The G-buffer normal of PIX, unit length (+y where the G-buffer holds none).
    glm::vec3 normalAt(std::size_t pix) const;
    // The facet normal of PIX, unit length (0 where the G-buffer holds none).
    glm::vec3 facetAt(std::size_t pix) const;
    // Whether a ray from pixel PIX (facet normal NG) in direction D leaves through its own
    // surface: the object casts and D lies on or below the facet's plane.
    bool throughOwnSurface(std::size_t pix, const glm::vec3& ng, const glm::vec3& d) const;
    // Where a ray from P in direction D starts: P lifted NEAR along the facet normal NG when D
    // leaves the facet's front, so that a grazing ray cannot re-enter the surface it starts on
    // from a position a rounding error behind it; else P.
    static glm::vec3 origin(const glm::vec3& p, const glm::vec3& ng, const glm::vec3& d,
                            float near);
    // The distance a ray from P skips and is lifted by: TNEAR (the casters' share), at least
    // what P's coordinates are rounded to far from the origin.
    static float nearFrom(const glm::vec3& p, float tnear);
};

}  // namespace penumbra::techniques::exact
