// Light-sample shadow maps: a perspective view from a point on a rect light that bounds every
// caster, batches of such maps rendered into one depth-texture array in a single instanced
// draw, and the pass that adds their weighted hard-shadow tests into a visibility target.
#pragma once

#include <glm/glm.hpp>

#include <map>
#include <span>
#include <vector>

#include "renderer/gl/dynamic_buffer.h"
#include "renderer/gl/handles.h"
#include "renderer/gl/program.h"
#include "renderer/passes/bindings.h"
#include "renderer/passes/fullscreen.h"
#include "renderer/passes/gbuffer.h"
#include "renderer/passes/gpu_scene.h"
#include "renderer/passes/light_depth.h"

namespace penumbra::passes {

// std430 mirror of glsl/common/sample_view.glsl.
struct SampleView {
    glm::mat4 view_proj{1.0f};
    glm::vec4 origin{0.0f};        // xyz point, w weight
    glm::vec4 forward{0.0f};       // xyz direction, w near
    glm::vec4 params{0.0f};        // x far, y texel world size per unit distance
    glm::vec4 light_origin{0.0f};  // (o.r, o.u, o.f, near) in the light's frame
    glm::vec4 frustum{0.0f};       // (left, bottom, 1/width, 1/height) at distance 1
    glm::vec4 depth{0.0f};         // (1/(far - near), weight, 0, 0)
};
static_assert(sizeof(SampleView) == SAMPLE_VIEW_SIZE, "SampleView: std430 size (mat4, 6 vec4)");
static_assert(sizeof(SampleView) == 160);

// The view from POINT (on the light) looking along the light's forward axis, frustum fitted to
// the CASTERS boxes that reach in front of the light.
SampleView makeSampleView(const scene::RectLight& light, const glm::vec3& point, Boxes casters,
                          float weight, int map_size);

// A depth-texture array of LAYERS maps of MAP_SIZE^2 and the light depth program that fills it.
class ShadowMapBatch {
public:
    ShadowMapBatch(int map_size, int layers, bool vertex_layer);
    // Renders VIEWS (at most layers()) into layers 0..n-1. VIEWS_BUFFER must hold them from
    // index VIEW_BASE on (bound to kBindingSampleViews by the caller).
    void render(const GpuScene& scene, int view_base, int count);
    // The same into layers FIRST_LAYER..FIRST_LAYER+COUNT-1, clearing only those (the others
    // keep their maps).
    void render(const GpuScene& scene, int view_base, int count, int first_layer);

    int layers() const { return layers_; }
    int mapSize() const { return map_size_; }
    const gl::Texture& depth() const { return depth_; }

private:
    int map_size_, layers_;
    bool vertex_layer_;
    gl::Texture depth_;
    gl::Framebuffer fbo_;
    gl::Program program_;
};

struct ShadowTestSettings {
    int pcf = 1;                 // kernel width in texels
    float normal_offset = 1.5f;  // texels
    float depth_bias = 0.0005f;  // linear depth units
};

// Adds sum_k weight_k * lit_k over a batch into the bound framebuffer's colour 0 (the caller
// sets additive blending).
class ShadowAccumulate {
public:
    ShadowAccumulate();
    // LIGHT gives the frame (right, up, forward) shared by every view of the batch.
    // CASTER_FLAGS (GpuScene::casterFlags()): on objects that cast, a sample below the
    // receiver's tangent plane is hidden by the receiver's own surface.
    void render(const GBuffer& gbuffer, const ShadowMapBatch& batch, int view_base, int count,
                const scene::RectLight& light, const ShadowTestSettings& settings,
                const gl::Buffer& caster_flags);

private:
    // The program for a PCF kernel of PCF texels, built on first use (glsl/passes/
    // shadow_accumulate.frag's PCF; a kernel width in a uniform ran the kernel's loop for every
    // pixel on llvmpipe even at 1: the test 1.1-1.2x slower).
    const gl::Program& program(int pcf);

    std::map<int, gl::Program> programs_;
    Fullscreen fullscreen_;
};

// A growable SSBO of SampleViews bound at kBindingSampleViews, and their lookup vectors in a
// uniform block at kBindingSampleLookups (at most kMaxSampleLookups views).
class SampleViewBuffer {
public:
    void upload(std::span<const SampleView> views);

private:
    gl::DynamicBuffer views_{"sample views"};
    gl::DynamicBuffer lookups_{"sample lookups"};
    std::vector<glm::vec4> staging_;
};

}  // namespace penumbra::passes
