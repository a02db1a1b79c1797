// The render targets of `ssm`: linear-depth maps (occluder and receiver maps) and soft shadow
// maps (summed micro-patch occlusion, blended additively at FP32 or FP16).
#pragma once

#include <glm/glm.hpp>

#include "renderer/gl/handles.h"
#include "renderer/gl/program.h"
#include "renderer/passes/gpu_scene.h"

namespace penumbra::techniques::ssm {

// A depth-only target of SIZE^2 texels (linear depth written by depth.frag).
struct DepthTarget {
    int size;
    gl::Texture depth;
    gl::Framebuffer fbo;
    DepthTarget(int size, const char* label);

    // Renders the objects FILTER selects through VIEW_PROJ with PROGRAM (techniques/ssm/depth.*),
    // storing (distance along LIGHT's forward axis - NEAR) * INV_RANGE: the nearest surface, or
    // the farthest when FARTHEST. Used by `ssm` and `css`.
    void render(const passes::GpuScene& scene, const gl::Program& program,
                passes::GpuScene::Filter filter, const glm::mat4& view_proj,
                const scene::RectLight& light, float near, float inv_range, bool farthest) const;
};

// A soft shadow map of SIZE^2 texels in FORMAT (GL_R32F or GL_R16F), filtered bilinearly when
// projected onto the receivers.
struct SoftShadowTarget {
    gl::Texture occlusion;
    gl::Framebuffer fbo;
    SoftShadowTarget(int size, GLenum format, const char* label);
};

}  // namespace penumbra::techniques::ssm
