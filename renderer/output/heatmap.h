// Error heatmaps for sweeps and reports: |ref - test| of one channel through a perceptually
// ordered colour ramp (black, purple, orange, yellow, white), written as a PNG.
#pragma once

#include <filesystem>
#include <string>

#include "renderer/output/image.h"

namespace penumbra::output {

// Colour for T in [0, 1] (clamped), as 8-bit RGB.
void heatColour(float t, unsigned char rgb[3]);

// Writes |REF - TEST| of CHANNEL, scaled so that FULL_SCALE maps to white. Pixels where REF has
// no geometry (A == 0, if REF has A) are drawn dark grey. Throws RuntimeError/CompareMismatch.
void writeErrorHeatmap(const std::filesystem::path& path, const Image& ref, const Image& test,
                       const std::string& channel, float full_scale);

}  // namespace penumbra::output
