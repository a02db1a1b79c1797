// Atomic file writes: a temporary name beside the target, then rename, so a killed job never
// leaves a partial file under the final name. Shared by the EXR, PNG and JSON writers.
#pragma once

#include <filesystem>
#include <functional>
#include <string>

namespace penumbra {

// "<dir>/.<name>.<pid>.tmp": hidden, unique per process, in the target's folder (same device).
std::filesystem::path temporaryPathFor(const std::filesystem::path& path);

// Creates PATH's parent folders, calls WRITE(temporary path), then renames it to PATH.
// Something other than a regular file at PATH (a device, FIFO, folder or link) is not replaced.
// On any failure the temporary file is removed and RuntimeError names PATH.
void writeAtomically(const std::filesystem::path& path,
                     const std::function<void(const std::filesystem::path&)>& write);

// For checking outputs before any work: throws InputError("LABEL: PATH: ...") when
// writeAtomically would refuse to replace what is at PATH.
void checkOutputPath(const std::filesystem::path& path, const std::string& label);

// Writes TEXT to PATH atomically.
void writeFileAtomically(const std::filesystem::path& path, const std::string& text);

}  // namespace penumbra
