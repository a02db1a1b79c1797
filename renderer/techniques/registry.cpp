// The technique registry: every technique the product knows, in listing order.
#include <array>
#include <functional>

#include "renderer/techniques/registry_entries.h"

namespace penumbra::techniques {

std::span<const TechniqueInfo> allTechniques() {
    static const std::array<TechniqueInfo, 7> all = {
        kHardTechnique, kReferenceTechnique, kExactTechnique, kAdaptiveTechnique,
        kSsmTechnique,  kBitmaskTechnique,   kCssTechnique};
    return all;
}

const TechniqueInfo* findTechnique(std::string_view name) {
    for (const auto& t : allTechniques())
        if (t.name == name) return &t;
    return nullptr;
}

}  // namespace penumbra::techniques
