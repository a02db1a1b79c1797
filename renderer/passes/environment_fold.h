// Folds lights a batch at a time into an irradiance sum (shadowed rgb, unshadowed luminance a),
// the layer the shade pass adds for an environment: a frame that renders hundreds of lights made
// of an environment keeps a batch of layers for them and the sum, not a layer each.
#pragma once

#include <vector>

#include "renderer/gl/dynamic_buffer.h"
#include "renderer/gl/handles.h"
#include "renderer/gl/program.h"
#include "renderer/passes/fullscreen.h"
#include "renderer/passes/gbuffer.h"
#include "renderer/scene/scene.h"

namespace penumbra::passes {

class EnvironmentFold {
public:
    // CASTER_FLAGS (GpuScene::casterFlags(), which must outlive this): the shade pass's horizon
    // rule (glsl/passes/shading.glsl).
    EnvironmentFold(int width, int height, const gl::Buffer& caster_flags);
    // Starts a sum of LIGHTS (indices below are into them).
    void begin(const std::vector<scene::RectLight>& lights);
    // Adds the terms of lights LIGHT .. LIGHT + COUNT - 1, from layers LAYER .. LAYER + COUNT - 1
    // of VISIBILITY_LAYERS (shading.glsl's layout).
    void add(const GBuffer& gbuffer, const gl::Texture& visibility_layers, int layer, int light,
             int count);
    // Lights a frame renders before each add(), a layer each: memory against passes. On
    // llvmpipe at 512 x 384 a pass per light cost 2.5x what the shade pass's loop over the lights
    // did, 8 a pass 1.3x, 16 1.2x; 8 keeps a 3840 x 2160 batch within llvmpipe's 2 GiB texture.
    static constexpr int kBatch = 8;
    // Copies the sum into layer LAYER of VISIBILITY_LAYERS (a separate texture until then: a
    // pass may not sample the array it draws into).
    void end(const gl::Texture& visibility_layers, int layer);

private:
    int width_, height_;
    const gl::Buffer& caster_flags_;
    gl::Texture sum_;
    gl::Framebuffer fbo_;
    gl::Program program_;
    gl::DynamicBuffer lights_{"environment lights"};
    Fullscreen fullscreen_;
};

}  // namespace penumbra::passes
