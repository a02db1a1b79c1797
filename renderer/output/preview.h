// Tone-mapped 8-bit PNG preview of the beauty channels (R, G, B): exposure, then a filmic
// curve and the sRGB transfer; written atomically like the EXR.
#pragma once

#include <filesystem>
#include <vector>

#include "renderer/output/image.h"

namespace penumbra::output {

// Writes 8-bit RGB pixels (rows top to bottom) as a PNG, atomically. Throws RuntimeError.
void writePngRgb8(const std::filesystem::path& path, int width, int height,
                  const std::vector<unsigned char>& rgb8);

// Throws RuntimeError naming PATH on failure, InputError if IMAGE lacks R, G or B.
void writePngPreview(const std::filesystem::path& path, const Image& image, float exposure = 0.0f);

}  // namespace penumbra::output
