// Technique parameters: one constexpr table per technique is the single source of truth for
// -D overrides, the scene's technique block, `penumbra techniques`, validation and outputs.
#pragma once

#include <span>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace penumbra {

enum class ParamType { Int, Float, Bool, Enum, String };

struct ParamSpec {
    std::string_view key;
    ParamType type;
    double def = 0;             // Int, Float, Bool (0/1)
    double min = 0, max = 0;    // Int, Float: inclusive range
    std::string_view choices;   // Enum: "a|b|c"
    std::string_view enum_def;  // Enum: the default choice; String: the default text
    std::string_view doc;       // one line
};

constexpr ParamSpec intParam(std::string_view key, int def, int min, int max,
                             std::string_view doc) {
    return {key, ParamType::Int, double(def), double(min), double(max), {}, {}, doc};
}
constexpr ParamSpec floatParam(std::string_view key, double def, double min, double max,
                               std::string_view doc) {
    return {key, ParamType::Float, def, min, max, {}, {}, doc};
}
constexpr ParamSpec boolParam(std::string_view key, bool def, std::string_view doc) {
    return {key, ParamType::Bool, def ? 1.0 : 0.0, 0, 1, {}, {}, doc};
}
constexpr ParamSpec enumParam(std::string_view key, std::string_view def, std::string_view choices,
                              std::string_view doc) {
    return {key, ParamType::Enum, 0, 0, 0, choices, def, doc};
}

// A free-form text value (e.g. a file path); DEF may be empty.
constexpr ParamSpec stringParam(std::string_view key, std::string_view def, std::string_view doc) {
    return {key, ParamType::String, 0, 0, 0, {}, def, doc};
}

std::string_view paramTypeName(ParamType type);
// The default as JSON, and the spec as JSON (for `techniques --json`).
nlohmann::json paramDefault(const ParamSpec& spec);
nlohmann::json paramSpecJson(const ParamSpec& spec);

// Resolved values of one technique's parameters: every key of its table, defaults filled in.
class Params {
public:
    Params() = default;
    explicit Params(nlohmann::json values) : values_(std::move(values)) {}
    int getInt(std::string_view key) const;
    double getFloat(std::string_view key) const;
    bool getBool(std::string_view key) const;
    std::string getString(std::string_view key) const;
    const nlohmann::json& json() const { return values_; }

private:
    const nlohmann::json& at(std::string_view key) const;
    nlohmann::json values_ = nlohmann::json::object();
};

// Checks BLOCK (the scene's technique object; its "name" is skipped) against SPECS: unknown
// keys, types and ranges, each an InputError "<where>.<key>: ...". WHERE is e.g.
// "scenes/x.json: technique".
Params resolveParams(std::span<const ParamSpec> specs, const nlohmann::json& block,
                     std::string_view where);

}  // namespace penumbra
