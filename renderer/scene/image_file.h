// Reading an image file that a scene names (an environment map, a budget map) with
// OpenImageIO: type and size checked before any pixel is read, every pixel finite.
#pragma once

#include <filesystem>
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

namespace penumbra::scene {

// Pixels as float, rows top first, CHANNELS interleaved.
struct FloatImage {
    int width = 0, height = 0, channels = 0;
    std::vector<float> pixels;
};

// Reads the first CHANNELS channels of PATH's first subimage (fewer where it has fewer), as
// stored (8- and 16-bit files scaled to [0, 1], no colour conversion). Its extension,
// lower-cased, must be one of EXTENSIONS ("expected " + EXPECTED otherwise); at most MAX_SIZE
// pixels per side. Throws InputError("<LABEL>: <what is wrong>"): missing, unreadable, wrong
// type, too large, or a non-finite pixel.
FloatImage readFloatImage(const std::filesystem::path& path, const std::string& label,
                          std::initializer_list<std::string_view> extensions,
                          std::string_view expected, int max_size, int channels);

}  // namespace penumbra::scene
