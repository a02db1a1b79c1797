// The output tests' lookup of an image's string attribute by name, shared by the EXR and
// Cryptomatte tests.
#pragma once

#include <string>

#include "renderer/output/image.h"

namespace penumbra::output::testing {

// IMAGE's attribute NAME, or "<missing>".
inline std::string attribute(const Image& image, const std::string& name) {
    for (const auto& [key, value] : image.attributes)
        if (key == name) return value;
    return "<missing>";
}

}  // namespace penumbra::output::testing
