// The shade pass: beauty from the G-buffer, every light's exact unshadowed irradiance and its
// visibility layer; also the irradiance-weighted visibility PRODUCT.md defines.
#pragma once

#include <vector>

#include "renderer/gl/dynamic_buffer.h"
#include "renderer/gl/handles.h"
#include "renderer/gl/program.h"
#include "renderer/passes/fullscreen.h"
#include "renderer/passes/gbuffer.h"
#include "renderer/scene/scene.h"

namespace penumbra::passes {

class Shade {
public:
    Shade(int width, int height);
    void render(const GBuffer& gbuffer, const gl::Texture& visibility_layers,
                const std::vector<scene::RectLight>& lights);
    const gl::Texture& beauty() const { return beauty_; }          // RGBA32F
    const gl::Texture& visibility() const { return visibility_; }  // R32F

private:
    int width_, height_;
    gl::Texture beauty_, visibility_;
    gl::Framebuffer fbo_;
    gl::Program program_;
    gl::DynamicBuffer lights_{"lights"};
    Fullscreen fullscreen_;
};

}  // namespace penumbra::passes
