// The one render sequence, shared by the render job, sweeps and the GL tests: a frame rendered
// (warm-up runs, then timed runs), read back as an image whose header names the technique and
// its resolved parameters, with no GL error left behind.
#pragma once

#include <functional>
#include <vector>

#include <nlohmann/json.hpp>

#include "renderer/core/params.h"
#include "renderer/frame/frame_renderer.h"
#include "renderer/frame/technique.h"
#include "renderer/gl/context.h"
#include "renderer/gl/pass_timer.h"
#include "renderer/output/image.h"
#include "renderer/scene/scene.h"

namespace penumbra::frame {

// How often a frame is rendered: WARMUP untimed runs, then REPEAT timed ones.
struct FrameRuns {
    int warmup = 0;
    int repeat = 1;
};

// One timed run: its wall-clock time (render to glFinish) and its passes in order.
struct TimedRun {
    double frame_ms = 0;
    std::vector<gl::PassTime> passes;
};

struct RenderedFrame {
    // Channels of PRODUCT.md; attributes penumbra/version, /commit, /technique, /params.
    output::Image image;
    nlohmann::json stats;        // the technique statistics of the last run
    std::vector<TimedRun> runs;  // the timed runs (not the warm-up)
    double readback_ms = 0;      // CPU time of reading the image back (on the GL thread)
    // renderFrameDeferred only: the copies under way; IMAGE has its attributes but no
    // channels until finishImage.
    FrameReadback readback;
};

// Renders S with RENDERER's technique and PARAMS (the technique is recreated when they
// changed), every pass timed by TIMER, RUNS times; reads the image back. Throws RuntimeError on
// a GL error.
RenderedFrame renderFrame(FrameRenderer& renderer, const scene::Scene& s, const Params& params,
                          gl::PassTimer& timer, FrameRuns runs);

// The same with the readback only started (pixel buffers) at the end of the frame, so the
// caller can render on while it completes: then R.readback.wait() on the GL thread (its time
// is the caller's to add to readback_ms), and finishImage(R) on any thread, while RENDERER lives.
RenderedFrame renderFrameDeferred(FrameRenderer& renderer, const scene::Scene& s,
                                  const Params& params, gl::PassTimer& timer, FrameRuns runs);
// Assembles R's waited-for readback into R.image's channels (their storage from BUFFERS when
// given, which then outlives the image's writing) and frees the readback.
void finishImage(RenderedFrame& r, output::PixelBuffers* buffers = nullptr);

// The same for a single frame with its own renderer and timer; CONFIGURE (if any) sees the
// renderer before it renders.
RenderedFrame renderFrame(const gl::ContextInfo& gl, const scene::Scene& s,
                          const TechniqueInfo& technique, const Params& params, FrameRuns runs = {},
                          const std::function<void(FrameRenderer&)>& configure = {});

}  // namespace penumbra::frame
