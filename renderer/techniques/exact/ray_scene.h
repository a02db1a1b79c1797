// The scene's shadow casters as an Embree 3 scene, for `exact`'s shadow rays: the same
// triangles and transforms the rasteriser draws, rebuilt only when a transform changes.
#pragma once

#include <vector>

#include <embree3/rtcore.h>
#include <glm/glm.hpp>

#include "renderer/scene/scene.h"

namespace penumbra::techniques::exact {

class RayScene {
public:
    RayScene();
    ~RayScene();
    RayScene(const RayScene&) = delete;
    RayScene& operator=(const RayScene&) = delete;

    // Takes SCENE's casters (ShadowRole Both or Occluder) in world space; rebuilds the BVH
    // only when the casters' transforms differ from the last call's.
    void update(const scene::Scene& scene);
    // Eight segments at once, from ORIGINS[i] to ORIGINS[i] + DIRS[i] (ACTIVE lanes only),
    // each starting NEAR (a world distance) from its origin: sets HIT[i]. Thread-safe after
    // update().
    void occluded8(const glm::vec3 origins[8], const glm::vec3 dirs[8], const bool active[8],
                   float near, bool hit[8]) const;

    size_t triangles() const { return triangles_; }
    // The world bounding-box diagonal of the casters (0 when there are none).
    float extent() const { return extent_; }
    // A distance from P beyond which no caster lies (for rays toward the environment).
    float reach(const glm::vec3& p) const { return glm::length(p - centre_) + extent_ + 1.0f; }

private:
    RTCDevice device_ = nullptr;
    RTCScene scene_ = nullptr;
    std::vector<glm::mat4> transforms_;  // of the last build, one per caster object
    size_t triangles_ = 0;
    float extent_ = 0;
    glm::vec3 centre_{0.0f};
};

}  // namespace penumbra::techniques::exact
