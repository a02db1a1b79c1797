// The render targets of `ssm` beyond the shared light depth maps and its receiver layers: soft
// shadow maps (summed micro-patch occlusion per receiver layer, blended additively at FP32 or
// FP16) and the soft shadow maps' window.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "renderer/gl/handles.h"
#include "renderer/passes/light_depth.h"
#include "renderer/passes/light_windows.h"

namespace penumbra::techniques::ssm {

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
                                     const passes::LightWindow& occluders, passes::Boxes receivers);

}  // namespace penumbra::techniques::ssm
