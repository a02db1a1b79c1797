// Nesting limits and short quotations for untrusted JSON: see json_bounds.h.
#include "renderer/core/json_bounds.h"

#include <cmath>

#include "renderer/core/error.h"

namespace penumbra {
namespace {

constexpr std::size_t kMaxQuote = 80;

// TEXT (cut to the quote length) as a JSON string; a cut UTF-8 sequence becomes U+FFFD.
std::string jsonString(std::string_view text) {
    return nlohmann::json(quoteText(text))
        .dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

// Appends VALUE's compact JSON to OUT until OUT is longer than kMaxQuote; each level adds a
// character before recursing, so the recursion is at most kMaxQuote + 1 deep.
void appendBounded(const nlohmann::json& value, std::string& out) {
    if (out.size() > kMaxQuote) return;
    if (value.is_array()) {
        out += '[';
        bool first = true;
        for (const auto& item : value) {
            if (out.size() > kMaxQuote) return;
            if (!first) out += ',';
            first = false;
            appendBounded(item, out);
        }
        out += ']';
    } else if (value.is_object()) {
        out += '{';
        bool first = true;
        for (const auto& [key, item] : value.items()) {
            if (out.size() > kMaxQuote) return;
            if (!first) out += ',';
            first = false;
            out += jsonString(key) + ':';
            appendBounded(item, out);
        }
        out += '}';
    } else if (value.is_string()) {
        out += jsonString(value.get_ref<const std::string&>());
    } else if (value.is_number_float() && !std::isfinite(value.get<double>())) {
        const double v = value.get<double>();
        out += std::isnan(v) ? "nan" : v > 0 ? "inf" : "-inf";  // dump() would say null
    } else {
        out += value.dump();
    }
}

}  // namespace

void checkJsonDepth(int depth, nlohmann::json::parse_event_t event, const std::string& label) {
    using Event = nlohmann::json::parse_event_t;
    if ((event == Event::object_start || event == Event::array_start) && depth >= kMaxJsonDepth)
        throw InputError(label + ": nesting deeper than " + std::to_string(kMaxJsonDepth) +
                         " levels");
}

std::string jsonErrorMessage(const char* what) {
    std::string message = what;
    const std::size_t close = message.find("] ");
    if (message.rfind("[json.exception", 0) == 0 && close != std::string::npos)
        message.erase(0, close + 2);
    return message;
}

std::optional<nlohmann::json> parseJsonBounded(std::string_view text, const std::string& label,
                                               std::string* why) {
    auto limit = [&](int depth, nlohmann::json::parse_event_t event, nlohmann::json&) {
        checkJsonDepth(depth, event, label);
        return true;
    };
    try {
        return nlohmann::json::parse(text.begin(), text.end(), limit);
    } catch (const nlohmann::json::exception& e) {
        if (why) *why = jsonErrorMessage(e.what());
        return std::nullopt;
    }
}

std::string quoteText(std::string_view text) {
    if (text.size() <= kMaxQuote) return std::string(text);
    return std::string(text.substr(0, kMaxQuote - 3)) + "...";
}

std::string quoteJson(const nlohmann::json& value) {
    std::string out;
    appendBounded(value, out);
    return out.size() <= kMaxQuote ? out : out.substr(0, kMaxQuote - 3) + "...";
}

}  // namespace penumbra
