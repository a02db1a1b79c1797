// Reading a JSON document from disk with errors that name the file: unreadable files, syntax
// errors with the parser's line and column, and duplicate keys (which JSON parsers drop silently).
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

namespace penumbra::scene {

// Reads the whole regular file at PATH (at most MAX_BYTES). Throws InputError("<label>: ...").
std::string readTextFile(const std::filesystem::path& path, const std::string& label,
                         std::size_t max_bytes);

// Parses TEXT as JSON, refusing duplicate object keys and nesting deeper than kMaxJsonDepth.
// Errors start with LABEL.
nlohmann::json parseJsonText(const std::string& text, const std::string& label);

}  // namespace penumbra::scene
