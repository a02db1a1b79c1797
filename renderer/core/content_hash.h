// A short, stable hash of bytes (64-bit FNV-1a as 16 hex digits): cache keys and the scene's
// identity in output headers. Not cryptographic.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace penumbra {

std::string contentHash(std::string_view bytes);

// contentHash of the bytes of the file at PATH, read a block at a time; empty when it cannot
// be read whole.
std::string fileContentHash(const std::filesystem::path& path);

}  // namespace penumbra
