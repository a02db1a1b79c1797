// The frame's per-light output targets: the visibility layer of each light and the
// technique's diagnostic layers, bound as one framebuffer for the light being rendered.
#pragma once

#include <span>
#include <vector>

#include "renderer/gl/handles.h"

namespace penumbra::frame {

// Per-light output layers shared by the frame: visibility (RGBA32F array, one layer per light:
// r = the visible area fraction; g, b, a = the contribution-weighted sums and flag that
// glsl/passes/shading.glsl reads, 0 where a technique has none) and one R32F array per diagnostic
// channel.
class OutputTargets {
public:
    OutputTargets(int width, int height, int lights, int diagnostics);
    // Binds a framebuffer with colour 0 = visibility layer LIGHT, colour 1+i = diagnostic i's
    // layer LIGHT, viewport = image size; returns that framebuffer, for passes that write it
    // other than by drawing (a blit).
    GLuint bind(int light);
    // Replaces visibility layer LIGHT with RGBA (width x height x 4 floats, top row first): for
    // techniques that compute visibility on the CPU.
    void uploadVisibility(int light, std::span<const float> rgba);
    const gl::Texture& visibility() const { return visibility_; }
    const std::vector<gl::Texture>& diagnostics() const { return diagnostics_; }

private:
    int width_, height_;
    gl::Texture visibility_;
    std::vector<gl::Texture> diagnostics_;
    gl::Framebuffer fbo_;
};

}  // namespace penumbra::frame
