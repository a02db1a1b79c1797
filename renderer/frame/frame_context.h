// What a technique sees while rendering one light of one frame: the scene, its GPU copy, the
// G-buffer, the output targets (visibility and diagnostics layers of this light), statistics,
// and pass(), which wraps each pass in a debug group and a timer.
#pragma once

#include <functional>
#include <span>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "renderer/frame/output_targets.h"
#include "renderer/gl/pass_timer.h"
#include "renderer/passes/gbuffer.h"
#include "renderer/passes/gpu_scene.h"
#include "renderer/scene/scene.h"

namespace penumbra::frame {

class FrameContext {
public:
    FrameContext(const scene::Scene& s, const passes::GpuScene& g, const passes::GBuffer& gb,
                 const passes::CameraMatrices& cam, OutputTargets& targets, gl::PassTimer& timer,
                 nlohmann::json& st)
        : scene(s),
          gpu(g),
          gbuffer(gb),
          camera(cam),
          lights(s.lights),
          targets_(targets),
          timer_(timer),
          stats(st) {}

    const scene::Scene& scene;
    const passes::GpuScene& gpu;
    const passes::GBuffer& gbuffer;
    const passes::CameraMatrices& camera;
    // The lights rendered: the scene's own, then those the technique made of its environment.
    std::span<const scene::RectLight> lights;
    int light = -1;  // index into lights being rendered; -1 in the frame's own passes
    int layer = -1;  // its output layer where that is not LIGHT (a folded environment light)
    const scene::RectLight& currentLight() const { return lights[static_cast<size_t>(light)]; }
    // Whether the current light stands for part of the environment map.
    bool environmentLight() const { return light >= static_cast<int>(scene.lights.size()); }
    // Whether this is the environment's irradiance layer (after every light; see
    // EnvironmentLights), which has no currentLight().
    bool environmentLayer() const { return light == static_cast<int>(lights.size()); }

    // Runs FN as one named, timed pass. With several lights, a technique's pass (light >= 0)
    // gets "@<light>" appended.
    void pass(const std::string& name, const std::function<void()>& fn);
    // Binds this light's output layers and returns their framebuffer (see OutputTargets::bind).
    GLuint bindOutput() { return targets_.bind(outputLayer()); }
    // Replaces this light's visibility layer (see OutputTargets::uploadVisibility).
    void uploadVisibility(std::span<const float> rgba) {
        targets_.uploadVisibility(outputLayer(), rgba);
    }
    int outputLayer() const { return layer >= 0 ? layer : light; }
    // Shows STATUS (e.g. a CPU pass's share done and ETA) on the progress line, if any.
    void progress(const std::string& status) {
        if (timer_.on_begin) timer_.on_begin(status);
    }

private:
    OutputTargets& targets_;
    gl::PassTimer& timer_;

public:
    nlohmann::json& stats;  // technique statistics, summed over lights by the technique
};

}  // namespace penumbra::frame
