// Bounds on untrusted JSON: a nesting limit checked while parsing, before anything recurses over
// the document (copy, dump, compare), and short quotations of bad values for error messages.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace penumbra {

constexpr int kMaxJsonDepth = 256;  // arrays and objects nested in each other, the outermost is 1

// For a parser callback: throws InputError("LABEL: nesting deeper than 256 levels") when EVENT
// opens a container at DEPTH (nlohmann's depth: the containers around it) beyond the limit.
void checkJsonDepth(int depth, nlohmann::json::parse_event_t event, const std::string& label);

// nlohmann's exception text without its "[json.exception.parse_error.101] " prefix.
std::string jsonErrorMessage(const char* what);

// Parses TEXT with the depth limit (InputError naming LABEL). Invalid JSON gives nullopt and,
// when WHY is given, the parser's message.
std::optional<nlohmann::json> parseJsonBounded(std::string_view text, const std::string& label,
                                               std::string* why = nullptr);

// At most 80 characters of TEXT, "..." marking a cut, for quoting input in a message.
std::string quoteText(std::string_view text);

// VALUE as compact JSON (infinities as inf, -inf), cut at 80 characters; never serializes more
// than that.
std::string quoteJson(const nlohmann::json& value);

}  // namespace penumbra
