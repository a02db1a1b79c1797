// The render sequence: see render_frame.h.
#include "renderer/frame/render_frame.h"

#include <chrono>

#include "penumbra/version.h"
#include "renderer/gl/debug.h"

namespace penumbra::frame {
namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

}  // namespace

RenderedFrame renderFrameDeferred(FrameRenderer& renderer, const scene::Scene& s,
                                  const Params& params, gl::PassTimer& timer, FrameRuns runs) {
    renderer.setParams(params);
    RenderedFrame out;
    for (int run = 0; run < runs.warmup + runs.repeat; ++run) {
        const auto start = Clock::now();
        out.stats = renderer.render(s, timer);
        glFinish();
        const double frame_ms = msSince(start);
        std::vector<gl::PassTime> passes = timer.finishFrame();
        if (run >= runs.warmup) out.runs.push_back({frame_ms, std::move(passes)});
    }
    const auto read_start = Clock::now();
    out.readback = renderer.startReadback();
    out.readback_ms = msSince(read_start);
    out.image.attributes = {{"penumbra/version", PENUMBRA_VERSION},
                            {"penumbra/commit", PENUMBRA_COMMIT},
                            {"penumbra/technique", std::string(renderer.technique().name)},
                            {"penumbra/params", renderer.params().json().dump()}};
    gl::checkErrors(s.path.string());  // no GL error after any render, for every caller
    return out;
}

void finishImage(RenderedFrame& r, output::PixelBuffers* buffers) {
    output::Image image = assembleFrameImage(r.readback, buffers);
    image.attributes = std::move(r.image.attributes);
    r.image = std::move(image);
    r.readback = {};
}

RenderedFrame renderFrame(FrameRenderer& renderer, const scene::Scene& s, const Params& params,
                          gl::PassTimer& timer, FrameRuns runs) {
    RenderedFrame out = renderFrameDeferred(renderer, s, params, timer, runs);
    const auto wait_start = Clock::now();
    out.readback.wait();
    finishImage(out);
    out.readback_ms += msSince(wait_start);
    return out;
}

RenderedFrame renderFrame(const gl::ContextInfo& gl, const scene::Scene& s,
                          const TechniqueInfo& technique, const Params& params, FrameRuns runs,
                          const std::function<void(FrameRenderer&)>& configure) {
    FrameRenderer renderer(gl, s, technique, params);
    if (configure) configure(renderer);
    gl::PassTimer timer(gl.software);
    return renderFrame(renderer, s, params, timer, runs);
}

}  // namespace penumbra::frame
