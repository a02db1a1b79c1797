// Only regular files are read or replaced: an input FIFO or device would block or never end,
// and the atomic rename of an output would replace a device node, folder or link in its place.
#pragma once

#include <filesystem>
#include <string>

namespace penumbra {

// Why PATH cannot be read as an input file: "" for a regular file, else "no such file",
// "is a folder", "is a FIFO", "is a device", "is a socket", "is a symbolic link" (only when
// FOLLOW_SYMLINKS is false) or "not a regular file".
std::string notRegularFileReason(const std::filesystem::path& path, bool follow_symlinks = true);

// Throws InputError("LABEL: <reason>") unless PATH (symlinks followed) is a regular file.
void requireRegularFile(const std::filesystem::path& path, const std::string& label);

// Why an output may not be renamed onto PATH: "" when nothing or a regular file is there (the
// path itself, not a link's target), else the reason in notRegularFileReason's words.
std::string notReplaceableReason(const std::filesystem::path& path);

}  // namespace penumbra
