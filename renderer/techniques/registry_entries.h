// The TechniqueInfo of each technique, defined in its own file and listed by registry.cpp.
#pragma once

#include "renderer/techniques/technique.h"

namespace penumbra::techniques {
extern const TechniqueInfo kHardTechnique;
extern const TechniqueInfo kReferenceTechnique;
extern const TechniqueInfo kExactTechnique;
extern const TechniqueInfo kSsmTechnique;
extern const TechniqueInfo kAdaptiveTechnique;
extern const TechniqueInfo kBitmaskTechnique;
extern const TechniqueInfo kCssTechnique;
}  // namespace penumbra::techniques
