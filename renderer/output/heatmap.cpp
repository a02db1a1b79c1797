// Error heatmaps: see heatmap.h.
#include "renderer/output/heatmap.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "renderer/core/error.h"
#include "renderer/output/preview.h"

namespace penumbra::output {

void heatColour(float t, unsigned char rgb[3]) {
    // Stops of a magma-like ramp: dark for small errors, bright for large ones.
    static constexpr std::array<std::array<float, 3>, 5> kStops = {{{0.0f, 0.0f, 0.02f},
                                                                    {0.35f, 0.07f, 0.5f},
                                                                    {0.85f, 0.3f, 0.3f},
                                                                    {0.99f, 0.75f, 0.25f},
                                                                    {1.0f, 1.0f, 0.85f}}};
    if (!(t > 0.0f)) t = 0.0f;
    t = std::min(t, 1.0f) * static_cast<float>(kStops.size() - 1);
    const size_t i = std::min(static_cast<size_t>(t), kStops.size() - 2);
    const float f = t - static_cast<float>(i);
    for (int c = 0; c < 3; ++c) {
        float v =
            kStops[i][static_cast<size_t>(c)] * (1 - f) + kStops[i + 1][static_cast<size_t>(c)] * f;
        rgb[c] = static_cast<unsigned char>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
    }
}

namespace {

// Appends the colour bar under an RGB8 picture of WIDTH x HEIGHT (RGB): colourBarRows(HEIGHT)
// rows, 2 dark ones, then the ramp from 0 (left) to the full scale (right). Returns the rows
// of the whole picture.
int appendColourBar(std::vector<unsigned char>& rgb, int width, int height) {
    const size_t w = static_cast<size_t>(width);
    const size_t n = w * static_cast<size_t>(height);
    const int bar = colourBarRows(height);
    rgb.resize((n + w * static_cast<size_t>(bar)) * 3, 20);
    for (int row = 2; row < bar; ++row)
        for (size_t x = 0; x < w; ++x)
            heatColour(w > 1 ? static_cast<float>(x) / static_cast<float>(w - 1) : 1.0f,
                       &rgb[(n + static_cast<size_t>(row) * w + x) * 3]);
    return height + bar;
}

}  // namespace

void writeErrorHeatmap(const std::filesystem::path& path, const Image& ref, const Image& test,
                       const std::string& channel, float full_scale) {
    const ImageChannel* r = ref.find(channel);
    const ImageChannel* t = test.find(channel);
    if (!r || !t || ref.width != test.width || ref.height != test.height)
        throw RuntimeError(path.string() + ": heatmap needs channel '" + channel +
                           "' in two images of one size");
    const ImageChannel* alpha = ref.find("A");
    const size_t n = r->pixels.size();
    std::vector<unsigned char> rgb(n * 3);
    for (size_t i = 0; i < n; ++i) {
        unsigned char* px = &rgb[i * 3];
        if (alpha && alpha->pixels[i] == 0.0f) {
            px[0] = px[1] = px[2] = 40;
            continue;
        }
        heatColour(std::fabs(r->pixels[i] - t->pixels[i]) / full_scale, px);
    }
    writePngRgb8(path, ref.width, appendColourBar(rgb, ref.width, ref.height), rgb);
}

int colourBarRows(int height) {
    return 2 + std::max(6, height / 10);
}

float defaultDifferenceScale(const Image& diff) {
    float m = 0.0f;
    for (const auto& c : diff.channels)
        for (float v : c.pixels)
            if (std::isfinite(v)) m = std::max(m, v);
    return m > 0.0f ? m : 1.0f;
}

void writeDifferenceHeatmap(const std::filesystem::path& path, const Image& diff, float scale) {
    if (diff.width <= 0 || diff.height <= 0 || diff.channels.empty() || !(scale > 0.0f))
        throw RuntimeError(path.string() + ": nothing to draw (empty difference or scale <= 0)");
    const size_t n = static_cast<size_t>(diff.width) * static_cast<size_t>(diff.height);
    std::vector<unsigned char> rgb(n * 3);
    for (size_t i = 0; i < n; ++i) {
        float m = 0.0f;
        for (const auto& c : diff.channels) m = std::max(m, c.pixels[i]);  // inf stays inf
        heatColour(std::isnan(m) ? 1.0f : m / scale, &rgb[i * 3]);
    }
    writePngRgb8(path, diff.width, appendColourBar(rgb, diff.width, diff.height), rgb);
}

}  // namespace penumbra::output
