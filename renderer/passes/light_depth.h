// The light depth pass: every depth map rendered from a rect light (shadow-map batches from
// points on it, light-centred maps of linear depth, object ids or distances) draws through one
// program family, glsl/passes/light_depth.*, and the targets such maps are drawn into.
#pragma once

#include <glm/glm.hpp>

#include "renderer/gl/handles.h"
#include "renderer/gl/program.h"
#include "renderer/passes/gpu_scene.h"
#include "renderer/scene/scene.h"

namespace penumbra::passes {

// Binds FBO with a SIZE x SIZE viewport for a depth-tested (LESS, writing), unblended,
// unculled draw: the state of every light depth map.
void beginDepthMapDraw(GLuint fbo, int size);

// Sets PROGRAM's u_light_centre, u_light_right, u_light_up and u_light_forward
// (glsl/common/light_frame.glsl): the light's frame, in which shaders project receivers.
void setLightFrameUniforms(const gl::Program& program, const scene::RectLight& light);

// Throws naming LABEL when FBO is not complete.
void checkFramebuffer(const gl::Framebuffer& fbo, const char* label);

// The program of a shadow-map batch: instanced views from passes::SampleView (bound by the
// caller), one array layer per instance by gl_Layer when VERTEX_LAYER.
gl::Program buildSampleDepthProgram(const char* label, bool vertex_layer);

// A view from the light's centre through VIEW_PROJ that stores (distance along the light's
// forward axis - NEAR) * INV_RANGE.
struct LightDepthView {
    glm::mat4 view_proj{1.0f};
    float near = 0.0f, inv_range = 1.0f;
};

// A light-centred depth program and its draw.
class LightDepthPass {
public:
    enum class Output {
        Depth,           // linear depth in the depth buffer
        DepthAndIds,     // and each surface's object id in colour 0 (R32I)
        Distance,        // the distance itself as (min, max) in colour 0 (RG32F), no depth range
        DistanceAndIds,  // and (object id, 1e30) in colour 1 (RG32F, DistancePyramid's owners)
        Range,           // linear depth in colours 0 and 1, for LightDepthRangeTarget
    };
    LightDepthPass(const char* label, Output output);
    // Depth with the world position and normal passed on to FRAGMENT, a technique's own
    // fragment shader (receiver peeling); IDS defined 1 in it with WITH_IDS, else 0.
    LightDepthPass(const char* label, const char* fragment, bool with_ids = false);

    // Draws the objects FILTER selects through VIEW into the bound target (its state set by
    // the caller, e.g. beginDepthMapDraw); leaves the program in use.
    void draw(const GpuScene& scene, GpuScene::Filter filter, const scene::RectLight& light,
              const LightDepthView& view) const;
    const gl::Program& program() const { return program_; }

private:
    Output output_;
    gl::Program program_;
};

// A light depth target of SIZE^2 texels (linear depth), with WITH_IDS also the object id of
// the surface at each texel (R32I, -1 where none).
struct LightDepthTarget {
    int size;
    gl::Texture depth;
    gl::Texture ids;  // WITH_IDS only
    gl::Framebuffer fbo;
    LightDepthTarget(int size, const char* label, bool with_ids = false);

    // Clears and draws the objects FILTER selects with PASS through VIEW: the nearest surface,
    // or the farthest when FARTHEST.
    void render(const GpuScene& scene, const LightDepthPass& pass, GpuScene::Filter filter,
                const scene::RectLight& light, const LightDepthView& view, bool farthest) const;
};

// The nearest and the farthest linear depth of every texel of a SIZE^2 map (R32F each; 1 and
// 0 where no surface), drawn in one draw through a LightDepthPass with Output::Range: MIN and
// MAX blending instead of two depth-tested draws, so the objects' vertices are processed once
// (on llvmpipe, which does that on one thread, the engine's second draw cost twice its first).
struct LightDepthRangeTarget {
    int size;
    gl::Texture nearest, farthest;
    gl::Framebuffer fbo;
    LightDepthRangeTarget(int size, const char* label);

    // Clears and draws the objects FILTER selects with PASS through VIEW.
    void render(const GpuScene& scene, const LightDepthPass& pass, GpuScene::Filter filter,
                const scene::RectLight& light, const LightDepthView& view) const;
};

}  // namespace penumbra::passes
