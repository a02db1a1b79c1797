// Parameter tables and their validation: see params.h.
#include "renderer/core/params.h"

#include <cctype>
#include <cmath>
#include <stdexcept>

#include "renderer/core/did_you_mean.h"
#include "renderer/core/error.h"
#include "renderer/core/json_field.h"

namespace penumbra {

std::string_view paramTypeName(ParamType type) {
    switch (type) {
        case ParamType::Int:
            return "int";
        case ParamType::Float:
            return "float";
        case ParamType::Bool:
            return "bool";
        case ParamType::Enum:
            return "enum";
        case ParamType::String:
            return "string";
    }
    return "?";
}

std::string_view paramGpuKindName(ParamGpu gpu) {
    switch (gpu) {
        case ParamGpu::Host:
            return "host";
        case ParamGpu::Uniform:
            return "uniform";
        case ParamGpu::Define:
            return "define";
    }
    return "?";
}

std::string paramGpuName(const ParamSpec& s) {
    if (s.gpu == ParamGpu::Host) return "";
    if (!s.gpu_name.empty()) return std::string(s.gpu_name);
    if (s.gpu == ParamGpu::Uniform) return "u_" + std::string(s.key);
    std::string macro(s.key);
    for (char& ch : macro) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
    return macro;
}

std::string_view glLimitName(GlLimit limit) {
    switch (limit) {
        case GlLimit::None:
            return "";
        case GlLimit::MaxTextureSize:
            return "GL_MAX_TEXTURE_SIZE";
    }
    return "?";
}

nlohmann::json paramDefault(const ParamSpec& s) {
    switch (s.type) {
        case ParamType::Int:
            return static_cast<long long>(s.def);
        case ParamType::Float:
            return s.def;
        case ParamType::Bool:
            return s.def != 0;
        case ParamType::Enum:
        case ParamType::String:
            return std::string(s.enum_def);
    }
    return nullptr;
}

nlohmann::json paramSpecJson(const ParamSpec& s) {
    nlohmann::json j = {{"key", s.key},
                        {"type", paramTypeName(s.type)},
                        {"default", paramDefault(s)},
                        {"doc", s.doc}};
    if (s.type == ParamType::Int)
        j["range"] = {static_cast<long long>(s.min), static_cast<long long>(s.max)};
    if (s.type == ParamType::Float) j["range"] = {s.min, s.max};
    if (s.type == ParamType::Enum) {
        j["choices"] = nlohmann::json::array();
        for (std::string_view c : s.choices) j["choices"].push_back(std::string(c));
    }
    j["gpu"] = paramGpuKindName(s.gpu);
    if (s.gpu != ParamGpu::Host) j["glsl"] = paramGpuName(s);
    if (s.limited_by != GlLimit::None) j["limited_by"] = glLimitName(s.limited_by);
    return j;
}

const nlohmann::json& Params::at(std::string_view key) const {
    auto it = values_.find(std::string(key));
    if (it == values_.end())
        throw std::logic_error("parameter '" + std::string(key) + "' is not in the table");
    return *it;
}

int Params::getInt(std::string_view key) const {
    return at(key).get<int>();
}
double Params::getFloat(std::string_view key) const {
    return at(key).get<double>();
}
bool Params::getBool(std::string_view key) const {
    return at(key).get<bool>();
}
std::string Params::getString(std::string_view key) const {
    return at(key).get<std::string>();
}

Params resolveParams(std::span<const ParamSpec> specs, const nlohmann::json& block,
                     std::string_view where) {
    const std::string prefix = std::string(where) + ".";
    if (!block.is_object()) failExpected("", std::string(where), "an object", block);
    for (const auto& [key, value] : block.items()) {
        if (key == "name") continue;
        bool known = false;
        for (const auto& s : specs) known = known || s.key == key;
        if (!known) {
            std::string allowed;
            std::vector<std::string_view> names;
            for (const auto& s : specs) {
                allowed += (allowed.empty() ? "" : ", ") + std::string(s.key);
                names.push_back(s.key);
            }
            const std::string near = nearestName(key, names);
            const auto name = block.find("name");
            const std::string technique =
                name != block.end() && name->is_string() ? name->get<std::string>() : "?";
            throw InputError(prefix + key + ": unknown parameter for technique '" + technique +
                             "' (" + (near.empty() ? "" : "did you mean '" + near + "'? ") +
                             "known: " + (allowed.empty() ? "none" : allowed) + ")");
        }
    }
    nlohmann::json out = nlohmann::json::object();
    const std::string no_file;
    const Field root(&block, std::string(where), no_file);
    for (const auto& s : specs) {
        const std::string key(s.key);
        const Field v = root.member(key);
        if (!v.present()) {
            out[key] = paramDefault(s);
            continue;
        }
        switch (s.type) {
            case ParamType::Int:
                out[key] = static_cast<long long>(
                    v.integer(static_cast<long>(s.min), static_cast<long>(s.max)));
                break;
            case ParamType::Float:
                out[key] = v.number(s.min, s.max);
                break;
            case ParamType::Bool:
                out[key] = v.boolean();
                break;
            case ParamType::Enum:
                out[key] = v.choice(s.choices);
                break;
            case ParamType::String:
                out[key] = v.string();
                break;
        }
    }
    return Params(std::move(out));
}

}  // namespace penumbra
