// A multi-channel float image as the renderer hands it to the writers and as `compare` reads
// it back: named channels, each stored as float and written as half or float.
#pragma once

#include <array>
#include <string>
#include <utility>
#include <vector>

#include "renderer/output/pixel_buffers.h"

namespace penumbra::output {

enum class PixelType { Half, Float };

struct ImageChannel {
    std::string name;  // EXR channel name: "R", "Z", "P.X", "visibility", "adaptive.maps", ...
    PixelType type = PixelType::Float;
    std::vector<float> pixels;  // width * height, row-major, row 0 = top of the picture
};

struct Image {
    int width = 0;
    int height = 0;
    std::vector<ImageChannel> channels;
    // Header attributes written as EXR string attributes (e.g. "penumbra/technique").
    std::vector<std::pair<std::string, std::string>> attributes;
    // Typed header attributes: EXR int, float and M44f ("penumbra/frame", "fov",
    // "worldToNDC"). A matrix is m[4 * row + column] as Imath stores it: points are row
    // vectors, p' = p * M, the translation in m[12..14].
    std::vector<std::pair<std::string, int>> int_attributes;
    std::vector<std::pair<std::string, float>> float_attributes;
    std::vector<std::pair<std::string, std::array<float, 16>>> matrix_attributes;
    // Where add() and the EXR writer take their pixel storage from when set (a sequence's
    // buffers, kept alive by the caller while the image is built and written); else new.
    PixelBuffers* buffers = nullptr;

    const ImageChannel* find(const std::string& name) const {
        for (const auto& c : channels)
            if (c.name == name) return &c;
        return nullptr;
    }
    // The reference stays valid until the next add() unless channels was reserved beforehand.
    // A channel of width x height pixels: zeros, or (FILL Undefined, with `buffers`) whatever
    // its reused storage held, for a caller that writes every pixel.
    ImageChannel& add(std::string name, PixelType type, Fill fill = Fill::Zeros) {
        const size_t n = static_cast<size_t>(width) * static_cast<size_t>(height);
        channels.push_back({std::move(name), type,
                            buffers ? buffers->take(n, fill) : std::vector<float>(n, 0.0f)});
        return channels.back();
    }
};

}  // namespace penumbra::output
