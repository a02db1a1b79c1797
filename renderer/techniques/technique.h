// The technique registry, and the frame layer's technique interface (renderer/frame/
// technique.h) under the names the techniques use: every technique includes this header.
#pragma once

#include <span>
#include <string_view>

#include "renderer/frame/technique.h"

namespace penumbra::techniques {

using frame::DiagnosticChannel;
using frame::EnvironmentLights;
using frame::Technique;
using frame::TechniqueInfo;

// Every registered technique, in listing order.
std::span<const TechniqueInfo> allTechniques();
// The technique called NAME, or nullptr.
const TechniqueInfo* findTechnique(std::string_view name);

}  // namespace penumbra::techniques
