// OpenEXR reading and writing. Writes are atomic: a temporary name in the same folder, then
// rename, so a killed job never leaves a half-written image under the final name.
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>

#include "renderer/output/image.h"

namespace penumbra::output {

// Thrown by readExr when the file is missing or not a readable EXR (compare exits 4).
class UnreadableImage : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Writes IMAGE to PATH atomically (core/atomic_file.h; ZIP compression). Creates missing parent folders.
// Throws RuntimeError naming PATH on failure; nothing is left under PATH then.
void writeExr(const std::filesystem::path& path, const Image& image);

// Reads every channel (as float) and the string attributes. Throws UnreadableImage.
Image readExr(const std::filesystem::path& path);


}  // namespace penumbra::output
