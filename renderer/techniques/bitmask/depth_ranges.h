// `bitmask`'s light depth map and its acceleration structures (Schwarz & Stamminger, 3 and 6):
// the HSM, a min/max mip pyramid of distances from the light's plane (passes::DistancePyramid,
// which `adaptive` shares); the MSSM, per texel the
// depth range of every power-of-two neighbourhood; the YSM, an MSSM built from a coarser HSM
// level. All are built on the GPU by compute shaders. With a far layer, also the nearest
// caster surface behind the map's (depth peeling) and its own min/max pyramid.
#pragma once

#include <memory>

#include <glm/glm.hpp>

#include "renderer/gl/handles.h"
#include "renderer/passes/distance_pyramid.h"
#include "renderer/passes/gpu_scene.h"
#include "renderer/passes/light_depth.h"
#include "renderer/scene/scene.h"

namespace penumbra::techniques::bitmask {

enum class Accel { Hsm, Mssm, Ysm };

class DepthRanges {
public:
    // MAP_SIZE (a power of two) texels per side; for the YSM, the MSSM part has YSM_SIZE;
    // FAR_LAYER: also the far layer (renderFarLayer()); OWN_IDS: each level 0 texel's object id
    // as well (hsmOwners(), farOwners()); OTHERS_FIRST: the far layer takes another object's
    // surface before the far side of the front texel's own (the map's ids, hsmOwners(), then
    // are kept whatever OWN_IDS).
    DepthRanges(int map_size, Accel accel, int ysm_size, bool far_layer = false,
                bool own_ids = false, bool others_first = false);

    // Renders the casters' distance along the light's forward axis (empty texels: kEmpty)
    // into HSM level 0, through VIEW_PROJ from the light's centre.
    void renderMap(const passes::GpuScene& scene, const scene::RectLight& light,
                   const glm::mat4& view_proj);
    // Renders the far layer's level 0 after renderMap(): per texel the distance of the nearest
    // caster surface more than kPeelGap (relative) beyond the map's, kEmpty where none; with
    // OTHERS_FIRST the nearest of another object than the map's there, where one is.
    void renderFarLayer(const passes::GpuScene& scene, const scene::RectLight& light,
                        const glm::mat4& view_proj);
    // Builds HSM levels 1.. from level 0 (and the far layer's, with one).
    void buildHsm();
    // Builds the MSSM (from HSM level 0) or the YSM's MSSM part (from HSM level mssmBase()).
    // The YSM's layer 0 is left unwritten: a query reaches the MSSM part only when its extent
    // at level mssmBase() is 3 texels or more (search.glsl), which layer 0 never serves.
    void buildMssm();

    int mapSize() const { return map_size_; }
    int levels() const { return hsm_.levels(); }
    int mssmBase() const { return mssm_base_; }  // the HSM level that is MSSM layer 0
    int mssmLayers() const { return mssm_layers_; }
    const gl::Texture& hsm() const { return hsm_.texture(); }  // RG32F mips: (min, max) distance
    const gl::Texture& mssm() const { return mssm_; }  // RG32F array, layer k: 2^k neighbourhoods
    // RG32F mips as hsm(); far layer only
    const gl::Texture& farLayer() const { return far_ ? far_->texture() : no_far_; }
    // RG32F mips, level 0 (object id of each texel's caster (-1: none), kEmpty); OWN_IDS only
    const gl::Texture& hsmOwners() const { return hsm_.owners(); }
    const gl::Texture& farOwners() const { return far_ ? far_->owners() : no_far_; }

    static constexpr float kEmpty = passes::DistancePyramid::kEmpty;  // where no caster is
    // A surface belongs to the far layer when it lies more than this fraction of the front's
    // distance behind it: the back of a closed caster, not the front's own triangles again.
    static constexpr float kPeelGap = 0.01f;

private:
    int map_size_, mssm_base_ = 0, mssm_layers_ = 0;
    bool ysm_ = false, others_first_ = false;
    passes::DistancePyramid hsm_;
    gl::Texture mssm_, no_far_;
    passes::LightDepthPass depth_pass_;                  // distances into HSM level 0
    std::unique_ptr<passes::DistancePyramid> far_;       // the far layer's, hsm_'s depth
    std::unique_ptr<passes::LightDepthPass> peel_pass_;  // the far layer's (peel.frag)
    gl::Program mssm_program_;
};

}  // namespace penumbra::techniques::bitmask
