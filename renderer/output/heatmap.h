// Error heatmaps for sweeps and reports: |ref - test| of one channel through a perceptually
// ordered colour ramp (black, purple, orange, yellow, white), written as a PNG.
#pragma once

#include <filesystem>
#include <string>

#include "renderer/output/image.h"

namespace penumbra::output {

// Colour for T in [0, 1] (clamped), as 8-bit RGB.
void heatColour(float t, unsigned char rgb[3]);

// Writes |REF - TEST| of CHANNEL, scaled so that FULL_SCALE maps to white, with the colour bar
// of writeDifferenceHeatmap below it (0 left, FULL_SCALE right). Pixels where REF has no
// geometry (A == 0, if REF has A) are drawn dark grey. Throws RuntimeError/CompareMismatch.
void writeErrorHeatmap(const std::filesystem::path& path, const Image& ref, const Image& test,
                       const std::string& channel, float full_scale);

// Writes DIFF (compare's difference image) as a PNG heatmap of the largest difference over its
// channels per pixel, SCALE mapping to white (infinite differences are white too), with a
// colour bar below it: a gap of 2 dark rows, then rows ramping from 0 (left) to SCALE (right).
// Throws RuntimeError naming PATH.
void writeDifferenceHeatmap(const std::filesystem::path& path, const Image& diff, float scale);

// The largest finite value of DIFF's channels: compare's default --diff-scale (1 when none is
// above 0).
float defaultDifferenceScale(const Image& diff);

// Rows of the colour bar (and its gap) under a heatmap of HEIGHT rows.
int colourBarRows(int height);

}  // namespace penumbra::output
