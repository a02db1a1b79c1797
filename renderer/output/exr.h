// OpenEXR reading and writing. Writes are atomic: a temporary name in the same folder, then
// rename, so a killed job never leaves a half-written image under the final name.
#pragma once

#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

#include "renderer/output/image.h"

namespace penumbra::output {

// Thrown by readExr when the file is missing or not a readable EXR (compare exits 4).
class UnreadableImage : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};
// Thrown by readExr for an image over its ExrReadLimits::max_side.
class ImageTooLarge : public UnreadableImage {
public:
    using UnreadableImage::UnreadableImage;
};

// How an EXR is compressed: OpenEXR's lossless methods only (the pixels read back are the ones
// written, whichever is used). LEVEL is zlib's (1 fastest to 9 smallest) for zip and zips. The
// default, zips (a zlib block per row), costs a sequence about a third less wall time per frame
// than zip (16 rows a block) with the writer overlapping the passes, for files 10% larger
// (scripts/bench frames, README).
struct ExrCompression {
    enum class Method { None, Rle, Zips, Zip, Piz };
    Method method = Method::Zips;
    int level = 4;  // OpenEXR 3.1's default
    bool operator==(const ExrCompression&) const = default;
};

// "zip", "zip:1" ... "zip:9", "zips[:LEVEL]", "rle", "none", "piz"; nullopt for anything else.
std::optional<ExrCompression> parseExrCompression(std::string_view text);
// The text parseExrCompression reads back ("zip:4").
std::string exrCompressionName(const ExrCompression& compression);
inline constexpr const char* kExrCompressionChoices =
    "zip, zips, rle, none or piz; zip and zips take a zlib level, zip:1 to zip:9";

// Writes IMAGE to PATH atomically (core/atomic_file.h; COMPRESSION, increasing Y, each
// channel as its `type`, attributes as string, int, float and M44f attributes). Creates missing
// parent folders. Throws RuntimeError naming PATH on failure (also for an empty image, a channel of
// the wrong size, duplicate channel or attribute names, or an attribute named like a standard one
// such as "compression"); nothing is left under PATH then.
void writeExr(const std::filesystem::path& path, const Image& image,
              const ExrCompression& compression = {});

// What readExr decodes: the first CHANNELS channels in reading order (0: every channel), and
// nothing of an image with a side over MAX_SIDE pixels (0: no limit), refused from its header.
// COLOUR_FIRST: where the file has no R, G or B channel, the first layer that has (its .R, .G,
// .B, .A: "diffuse.R", ...) comes first instead, else a Y (luminance) channel.
struct ExrReadLimits {
    int channels = 0;
    int max_side = 0;
    bool colour_first = false;
};

// Reads every channel (as float; `type` says how it was stored) and the string, int, float
// and M44f attributes but those every EXR header holds (other types are skipped too).
// Channels come in the order R, G, B, A, then the others alphabetically (EXR stores channels
// sorted by name, so the writer's order is not kept). Throws UnreadableImage naming PATH for a
// missing, unreadable, corrupt or truncated file, or one that is not a flat OpenEXR image;
// ImageTooLarge ("image too large (WxH, limit N)") for one over LIMITS.max_side.
Image readExr(const std::filesystem::path& path, const ExrReadLimits& limits = {});

// True when readExr(PATH) succeeds: a cached image (a sweep's reference or run) is reused only
// then, and rendered again when it is missing, truncated or corrupt.
bool isReadableExr(const std::filesystem::path& path);

}  // namespace penumbra::output
