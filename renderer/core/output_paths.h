// Output file names from patterns: a run of '#' becomes the zero-padded frame number; with
// several frames and no '#', ".####" goes before the extension (PRODUCT.md, --output).
#pragma once

#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace penumbra {

std::string expandFramePattern(std::string_view pattern, int frame, bool several_frames);

// PATH with its extension replaced by EXT (".json"), or EXT appended when it has none.
std::string replaceExtension(std::string_view path, std::string_view ext);

// What PATH names on disk, to tell whether two outputs clash: absolute and weakly canonical
// ("./y.exr", "y.exr" and "out/../y.exr" are one file; links followed where they exist).
std::string outputIdentity(const std::string& path);

// The outputIdentity of each of FILES, to test many outputs against them.
std::set<std::string> outputIdentities(const std::vector<std::string>& files);

// Whether PATH names one of FILES (compared by outputIdentity): an output that would overwrite
// an input of the same command.
bool namesAnyOf(const std::string& path, const std::vector<std::string>& files);

}  // namespace penumbra
