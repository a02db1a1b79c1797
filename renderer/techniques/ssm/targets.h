// The render targets of `ssm`: linear-depth maps (occluder and receiver maps) and soft shadow
// maps (summed micro-patch occlusion, blended additively at FP32 or FP16).
#pragma once

#include "renderer/gl/handles.h"

namespace penumbra::techniques::ssm {

// A depth-only target of SIZE^2 texels (linear depth written by depth.frag).
struct DepthTarget {
    gl::Texture depth;
    gl::Framebuffer fbo;
    DepthTarget(int size, const char* label);
};

// A soft shadow map of SIZE^2 texels in FORMAT (GL_R32F or GL_R16F), filtered bilinearly when
// projected onto the receivers.
struct SoftShadowTarget {
    gl::Texture occlusion;
    gl::Framebuffer fbo;
    SoftShadowTarget(int size, GLenum format, const char* label);
};

}  // namespace penumbra::techniques::ssm
