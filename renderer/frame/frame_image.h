// Assembles the output image of a frame from GPU textures: beauty, depth, position, normal,
// id, visibility (and `visibility.<light index>` with several lights) and the technique's
// diagnostic channels (PRODUCT.md, Outputs). The copies start at the end of the frame (pixel
// buffers, readback_pool.h) and the image is assembled later, on any thread.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "renderer/frame/frame_context.h"
#include "renderer/frame/technique.h"
#include "renderer/output/image.h"
#include "renderer/passes/gbuffer.h"
#include "renderer/passes/readback_pool.h"
#include "renderer/passes/shade.h"

namespace penumbra::frame {

using Read = std::unique_ptr<passes::PendingRead>;

// A frame's textures on their way to the CPU. Move-only; wait() on the GL thread before
// assembleFrameImage (which may then run on another thread).
struct FrameReadback {
    int width = 0, height = 0, lights = 0;
    std::string technique_name;
    std::vector<DiagnosticChannel> diagnostics;
    Read beauty, position, normal, id, visibility;
    std::vector<Read> light_visibility;         // with several scene lights: each one's layer
    std::vector<std::vector<Read>> diagnostic;  // [diagnostic][light]
    passes::ReadbackFence fence;
    // Waits until the copies are done (GL thread). Throws RuntimeError.
    void wait();
};

// Queues the copies of the frame's textures into POOL's buffers (GL thread). LIGHTS: the
// layers of TARGETS; the first SCENE_LIGHTS are the scene's `lights` (the rest, the lights a
// technique makes of the environment, get no channel of their own).
FrameReadback startFrameReadback(passes::ReadbackPool& pool, const passes::GBuffer& gbuffer,
                                 const passes::Shade& shade, const OutputTargets& targets,
                                 int lights, int scene_lights, const std::string& technique_name,
                                 const std::vector<DiagnosticChannel>& diagnostics);

// The image of a waited-for readback (rows top first), on any thread; no attributes. Its
// channels' storage comes from BUFFERS when given (the image's `buffers`).
output::Image assembleFrameImage(const FrameReadback& readback,
                                 output::PixelBuffers* buffers = nullptr);

}  // namespace penumbra::frame
