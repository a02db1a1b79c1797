// Dotted keys: splitting "lights.0.size" into components and finding the value they address
// inside a JSON document through nlohmann's json_pointer (see dotted_key.h).
#include "renderer/scene/dotted_key.h"

#include <charconv>

namespace penumbra::scene {

std::optional<std::vector<std::string>> splitDottedKey(std::string_view key) {
    std::vector<std::string> parts;
    std::size_t start = 0;
    while (true) {
        const std::size_t dot = key.find('.', start);
        const std::string_view part = key.substr(start, dot - start);
        if (part.empty()) return std::nullopt;
        parts.emplace_back(part);
        if (dot == std::string_view::npos) break;
        start = dot + 1;
    }
    return parts;
}

nlohmann::json::json_pointer toJsonPointer(const std::vector<std::string>& parts) {
    nlohmann::json::json_pointer pointer;
    for (const std::string& part : parts) pointer.push_back(part);
    return pointer;
}

std::optional<std::size_t> arrayIndex(const std::string& component) {
    if (component.empty() || (component.size() > 1 && component[0] == '0')) return std::nullopt;
    for (char c : component)
        if (c < '0' || c > '9') return std::nullopt;
    std::size_t value = 0;
    const auto [ptr, ec] =
        std::from_chars(component.data(), component.data() + component.size(), value);
    if (ec != std::errc() || ptr != component.data() + component.size())
        return static_cast<std::size_t>(-1);  // all digits but too large: never in range
    return value;
}

nlohmann::json* findAt(nlohmann::json& doc, const std::vector<std::string>& parts) {
    const nlohmann::json::json_pointer pointer = toJsonPointer(parts);
    try {
        // contains() is false for "00", "-" and indices past the end; it throws (out_of_range
        // 404) for an index too large for size_t, which addresses nothing either.
        return doc.contains(pointer) ? &doc.at(pointer) : nullptr;
    } catch (const nlohmann::json::exception&) {
        return nullptr;
    }
}

const nlohmann::json* findAt(const nlohmann::json& doc, const std::vector<std::string>& parts) {
    return findAt(const_cast<nlohmann::json&>(doc), parts);
}

}  // namespace penumbra::scene
