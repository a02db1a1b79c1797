// The render targets of `ssm` beyond the shared light depth maps: layered receiver maps peeled
// from the light's centre, soft shadow maps (summed micro-patch occlusion per receiver layer,
// blended additively at FP32 or FP16) and the soft shadow maps' window.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "renderer/gl/handles.h"
#include "renderer/gl/program.h"
#include "renderer/passes/fullscreen.h"
#include "renderer/passes/gpu_scene.h"
#include "renderer/passes/light_depth.h"
#include "renderer/passes/light_windows.h"

namespace penumbra::techniques::ssm {

// LAYERS receiver depth maps of SIZE^2 texels from the light's centre (a DEPTH32F array):
// layer 0 the nearest light-facing receiver surface, layer k the nearest one beyond layer k - 1
// (depth peeling), and with LAYERS > 1 the last the farthest one beyond the layer before it
// (so the floor under a deep stack of surfaces is always a layer); 1 where a layer has none.
struct ReceiverLayers {
    int size, layers;
    gl::Texture depth;  // 2D array, LAYERS layers
    gl::Texture ids;    // 2D array of the surfaces' object ids (R32I, -1 = none)
    passes::LightDepthTarget scratch;
    gl::Program resolve;       // techniques/ssm/peel_resolve.frag (the farthest layer)
    gl::Framebuffer last_fbo;  // the array's last layer as a depth target
    passes::Fullscreen fullscreen;
    ReceiverLayers(int size, int layers, const char* label);

    // Peels the objects FILTER selects through VIEW with PEEL (the light depth pass with
    // techniques/ssm/peel.frag), each layer at least GAP (normalised depth) beyond the one
    // before. Stops at the first empty layer; returns the layers that hold a receiver.
    int render(const passes::GpuScene& scene, const passes::LightDepthPass& peel,
               passes::GpuScene::Filter filter, const scene::RectLight& light,
               const passes::LightDepthView& view, float gap) const;
};

// Soft shadow maps of SIZE^2 texels in FORMAT (GL_R32F or GL_R16F), one per receiver layer (a
// 2D array), filtered bilinearly when projected onto the receivers.
struct SoftShadowTarget {
    gl::Texture occlusion;
    std::vector<gl::Framebuffer> fbos;  // one per layer
    SoftShadowTarget(int size, int layers, GLenum format, const char* label);
};

// W with its near plane pulled toward the light by the margin its far plane has (windowOf), so
// that a surface parallel to the light at W's nearest depth (a floor, a flat occluder) is not
// clipped away by the near plane.
passes::LightWindow withNearMargin(passes::LightWindow w);

// The soft-shadow-map window: the occluder window grown by the widest penumbra (section 3.3,
// half the light over the nearest occluder depth, less its value at the farthest receiver),
// clipped to the receivers' window, with the receivers' depth range.
passes::LightWindow softShadowWindow(const scene::RectLight& light,
                                     const passes::LightWindow& occluders,
                                     const passes::Bounds& receivers);

}  // namespace penumbra::techniques::ssm
