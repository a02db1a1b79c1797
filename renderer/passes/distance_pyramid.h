// A light-centred map of the casters' distances along the light's forward axis and its min/max
// mip pyramid (the HSM of Schwarz & Stamminger, 3): `bitmask`'s search, `adaptive`'s lit region.
#pragma once

#include <glm/glm.hpp>

#include "renderer/gl/handles.h"
#include "renderer/gl/program.h"
#include "renderer/passes/gpu_scene.h"
#include "renderer/passes/light_depth.h"
#include "renderer/scene/scene.h"

namespace penumbra::passes {

class DistancePyramid {
public:
    static constexpr float kEmpty = 1e30f;  // the distance stored where no caster is

    // SIZE (a power of two) texels per side, RG32F mips: (min, max) distance. SHARED_DEPTH: the
    // depth buffer its draws test against, that of another pyramid of the same size (each draw
    // clears it); without one it has its own. WITH_OWNERS: level 0 has each texel's owner too
    // (owners(), colour 1: (object id, kEmpty), (-1, kEmpty) where no caster is), written by a
    // draw with Output::DistanceAndIds.
    DistancePyramid(int size, const char* label, const gl::Texture* shared_depth = nullptr,
                    bool with_owners = false);

    // Binds level 0 as the target with distances cleared to kEmpty and depth to the far
    // plane, in the state of every light depth map; a LightDepthPass draw writing (d, d)
    // (Output::Distance, or a fragment shader of its own) follows, then endDraw().
    void beginDraw() const;
    static void endDraw();
    // Clears and draws the casters' distances with PASS (Output::Distance) through VIEW_PROJ.
    void render(const LightDepthPass& pass, const GpuScene& scene, const scene::RectLight& light,
                const glm::mat4& view_proj) const;
    // Builds levels 1.. from level 0: each texel the (min, max) of the 2 x 2 below it.
    void build() const;

    int size() const { return size_; }
    int levels() const { return levels_; }
    const gl::Texture& texture() const { return texture_; }
    const gl::Texture& depth() const { return depth_; }  // its own (empty with a shared one)
    // RG32F with the pyramid's levels (WITH_OWNERS; else empty): the draw writes level 0,
    // build() none (the levels above are bitmask::MicroRects')
    const gl::Texture& owners() const { return owners_; }

private:
    int size_, levels_;
    gl::Texture texture_, depth_, owners_;
    gl::Framebuffer fbo_;
    gl::Program program_;
};

}  // namespace penumbra::passes
