// The render targets of `ssm`: linear-depth maps (occluder map, layered receiver maps peeled
// from the light's centre) and soft shadow maps (summed micro-patch occlusion per receiver
// layer, blended additively at FP32 or FP16).
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "renderer/gl/handles.h"
#include "renderer/gl/program.h"
#include "renderer/passes/fullscreen.h"
#include "renderer/passes/gpu_scene.h"

namespace penumbra::techniques::ssm {

// A depth target of SIZE^2 texels (linear depth written by depth.frag), with WITH_IDS also the
// object id of the surface at each texel (R32I, -1 where none).
struct DepthTarget {
    int size;
    gl::Texture depth;
    gl::Texture ids;  // WITH_IDS only
    gl::Framebuffer fbo;
    DepthTarget(int size, const char* label, bool with_ids = false);

    // Renders the objects FILTER selects through VIEW_PROJ with PROGRAM (techniques/ssm/depth.*),
    // storing (distance along LIGHT's forward axis - NEAR) * INV_RANGE: the nearest surface, or
    // the farthest when FARTHEST. Used by `ssm` and `css`.
    void render(const passes::GpuScene& scene, const gl::Program& program,
                passes::GpuScene::Filter filter, const glm::mat4& view_proj,
                const scene::RectLight& light, float near, float inv_range, bool farthest) const;
};

// LAYERS receiver depth maps of SIZE^2 texels from the light's centre (a DEPTH32F array):
// layer 0 the nearest light-facing receiver surface, layer k the nearest one beyond layer k - 1
// (depth peeling), and with LAYERS > 1 the last the farthest one beyond the layer before it
// (so the floor under a deep stack of surfaces is always a layer); 1 where a layer has none.
struct ReceiverLayers {
    int size, layers;
    gl::Texture depth;  // 2D array, LAYERS layers
    gl::Texture ids;    // 2D array of the surfaces' object ids (R32I, -1 = none)
    DepthTarget scratch;
    gl::Program resolve;       // techniques/ssm/peel_resolve.frag (the farthest layer)
    gl::Framebuffer last_fbo;  // the array's last layer as a depth target
    passes::Fullscreen fullscreen;
    ReceiverLayers(int size, int layers, const char* label);

    // Peels the objects FILTER selects through VIEW_PROJ with PROGRAM (techniques/ssm/depth.vert
    // with PEEL, peel.frag), each layer at least GAP (normalised depth) beyond the one before.
    // Stops at the first empty layer; returns the layers that hold a receiver.
    int render(const passes::GpuScene& scene, const gl::Program& program,
               passes::GpuScene::Filter filter, const glm::mat4& view_proj,
               const scene::RectLight& light, float near, float inv_range, float gap) const;
};

// Soft shadow maps of SIZE^2 texels in FORMAT (GL_R32F or GL_R16F), one per receiver layer (a
// 2D array), filtered bilinearly when projected onto the receivers.
struct SoftShadowTarget {
    gl::Texture occlusion;
    std::vector<gl::Framebuffer> fbos;  // one per layer
    SoftShadowTarget(int size, int layers, GLenum format, const char* label);
};

}  // namespace penumbra::techniques::ssm
