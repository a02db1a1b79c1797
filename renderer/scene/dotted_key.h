// Dotted keys ("lights.0.size") that address a value inside a JSON document, shared by -D
// overrides and animation tracks: a thin translation to nlohmann::json::json_pointer, whose
// lookup is used as it is. Numeric components index arrays: plain decimal, no leading zero
// ("00" and json_pointer's past-the-end "-" address nothing); '~' and '/' in a component are
// ordinary characters (json_pointer::push_back keeps them as they are).
// Measured with nlohmann 3.11.2 (Debian 12): json_pointer's lookup (contains, at) keeps these
// rules, but its set (operator[]) does not: "/lights/-" appends, "/lights/3" on a 1-element
// array pads it with nulls, "/camera/new/0" creates an array. So -D's set walks the components
// itself (overrides.cpp), refusing each of those with a message that names the key.
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

// The json_pointer with PARTS as its reference tokens.
nlohmann::json::json_pointer toJsonPointer(const std::vector<std::string>& parts);

// The array index a component names ("3" -> 3), or nullopt when it is not plain decimal (a sign,
// a leading zero as in "03", "-"), json_pointer's rule for array indices.
std::optional<std::size_t> arrayIndex(const std::string& component);

// The value at PARTS inside DOC, or nullptr when some component is missing.
const nlohmann::json* findAt(const nlohmann::json& doc, const std::vector<std::string>& parts);
nlohmann::json* findAt(nlohmann::json& doc, const std::vector<std::string>& parts);

}  // namespace penumbra::scene
