// Tone-mapped 8-bit PNG preview of the beauty channels (R, G, B): exposure, then a filmic
// curve and the sRGB transfer; written atomically like the EXR.
#pragma once

#include <filesystem>

#include "renderer/output/image.h"

namespace penumbra::output {

// Throws RuntimeError naming PATH on failure, InputError if IMAGE lacks R, G or B.
void writePngPreview(const std::filesystem::path& path, const Image& image, float exposure = 0.0f);

}  // namespace penumbra::output
