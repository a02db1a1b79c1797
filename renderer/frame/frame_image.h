// Assembles the output image of a frame from GPU textures: beauty, depth, position, normal,
// id, visibility (and `visibility.<light index>` with several lights) and the technique's
// diagnostic channels (PRODUCT.md, Outputs).
#pragma once

#include <string>
#include <vector>

#include "renderer/frame/frame_context.h"
#include "renderer/frame/technique.h"
#include "renderer/output/image.h"
#include "renderer/passes/gbuffer.h"
#include "renderer/passes/shade.h"

namespace penumbra::frame {

output::Image readFrameImage(const passes::GBuffer& gbuffer, const passes::Shade& shade,
                             const OutputTargets& targets, int lights,
                             const std::string& technique_name,
                             const std::vector<DiagnosticChannel>& diagnostics);

}  // namespace penumbra::frame
