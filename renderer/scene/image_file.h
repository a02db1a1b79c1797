// Reading an image file that a scene names (an environment map, a budget map, an HDR glTF
// texture), OpenEXR with output/exr.h's reader and the rest with OpenImageIO: type, size and
// memory checked before any pixel is read, every pixel finite, no line of a decoder on stderr.
#pragma once

#include <cstddef>
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

// Reads the first CHANNELS channels of PATH's first subimage (fewer where it has fewer; an
// OpenEXR file's colour channels first, see output::ExrReadLimits::colour_first), as
// stored (8- and 16-bit files scaled to [0, 1], no colour conversion). Its extension,
// lower-cased, must be one of EXTENSIONS ("expected " + EXPECTED otherwise); at most MAX_SIZE
// pixels per side, and the decoded pixels within the memory limit (core/memory_limit.h).
// Rows are decoded a strip at a time, so a file whose header declares more pixels than it
// holds fails after decoding what it holds. Throws InputError("<LABEL>: <what is wrong>"):
// missing, unreadable, wrong type, too large, or a non-finite pixel.
FloatImage readFloatImage(const std::filesystem::path& path, const std::string& label,
                          std::initializer_list<std::string_view> extensions,
                          std::string_view expected, int max_size, int channels);

// The same checks for an image held in memory, its format named by EXTENSION (".hdr").
FloatImage readFloatImageFromMemory(const unsigned char* bytes, std::size_t size,
                                    std::string_view extension, const std::string& label,
                                    int max_size, int channels);

}  // namespace penumbra::scene
