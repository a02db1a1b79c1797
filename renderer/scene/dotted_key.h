// Dotted keys ("lights.0.size") that address a value inside a JSON document, shared by -D
// overrides and animation tracks. Numeric components index arrays.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

namespace penumbra::scene {

// Splits KEY at dots; nullopt when KEY or any component is empty.
std::optional<std::vector<std::string>> splitDottedKey(std::string_view key);

// The array index a component names ("3" -> 3), or nullopt when it is not all digits.
std::optional<std::size_t> arrayIndex(const std::string& component);

// The value at PARTS inside DOC, or nullptr when some component is missing.
const nlohmann::json* findAt(const nlohmann::json& doc, const std::vector<std::string>& parts);
nlohmann::json* findAt(nlohmann::json& doc, const std::vector<std::string>& parts);

}  // namespace penumbra::scene
