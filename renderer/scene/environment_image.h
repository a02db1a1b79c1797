// Loading an equirectangular environment map (.exr through the project's OpenEXR reader, .hdr
// through OpenImageIO) into linear RGB floats, size checked before any pixel is read.
#pragma once

#include <filesystem>
#include <memory>

#include "renderer/scene/scene.h"

namespace penumbra::scene {

constexpr int kMaxEnvironmentSize = 16384;  // width and height limit, pixels

// Throws InputError("<path>: <what is wrong>"): missing, unreadable, wrong type, too large,
// or with non-finite pixels. Negative values are clamped to 0; 1-2 channel images are grey.
std::shared_ptr<const EnvironmentImage> loadEnvironmentImage(const std::filesystem::path& path);

}  // namespace penumbra::scene
