// Technique parameters: one constexpr table per technique is the single source of truth for
// -D overrides, the scene's technique block, `penumbra techniques`, validation and outputs.
#pragma once

#include <array>
#include <cstddef>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>

#include <nlohmann/json.hpp>

namespace penumbra {

enum class ParamType { Int, Float, Bool, Enum, String };

// How a parameter reaches the GPU: read on the CPU only (Host), uploaded as a uniform of the
// technique's programs (Uniform; setParamUniforms in renderer/gl/param_uniforms.h), or
// injected as a #define when a program is built (Define; paramDefines).
enum class ParamGpu { Host, Uniform, Define };

// A GL limit a parameter's value must stay within (checked against the context before a render).
enum class GlLimit { None, MaxTextureSize };

struct ParamSpec {
    std::string_view key;
    ParamType type;
    double def = 0;                             // Int, Float, Bool (0/1)
    double min = 0, max = 0;                    // Int, Float: inclusive range
    std::span<const std::string_view> choices;  // Enum: the names, in the C++ enum's order
    std::string_view enum_def;  // Enum: the default choice; String: the default text
    std::string_view doc;       // one line
    ParamGpu gpu = ParamGpu::Host;
    std::string_view gpu_name;  // Uniform: GLSL name ("" = "u_<key>"); Define: macro ("" = KEY)
    GlLimit limited_by = GlLimit::None;

    // The same parameter, uploaded as the uniform NAME (by default "u_<key>").
    constexpr ParamSpec uniform(std::string_view name = {}) const {
        ParamSpec s = *this;
        s.gpu = ParamGpu::Uniform;
        s.gpu_name = name;
        return s;
    }
    // The same parameter, injected as `#define NAME value` (by default the key in capitals).
    constexpr ParamSpec define(std::string_view name = {}) const {
        ParamSpec s = *this;
        s.gpu = ParamGpu::Define;
        s.gpu_name = name;
        return s;
    }
    // The same parameter, bounded by the GL limit LIMIT as well as by its range.
    constexpr ParamSpec limitedBy(GlLimit limit) const {
        ParamSpec s = *this;
        s.limited_by = limit;
        return s;
    }
};

// The GLSL name of a Uniform or Define parameter (see ParamSpec::gpu_name); "" for Host.
std::string paramGpuName(const ParamSpec& spec);
std::string_view paramGpuKindName(ParamGpu gpu);
std::string_view glLimitName(GlLimit limit);

// An Enum parameter read as the C++ enum E: NAMES are its choices in enumerator order (the
// first names E's value 0). The table's spec is made from the key (enumParam) and the technique
// reads it with Params::getEnum, so the choices, the enum and the comparisons cannot drift: a
// misspelled enumerator does not compile, and the names are the ones users see and the README
// lists (tests/cli/techniques_readme.sh).
template <class E, std::size_t N>
struct EnumKey {
    std::string_view key;
    std::array<std::string_view, N> names;

    constexpr std::string_view name(E value) const {
        return names[static_cast<std::size_t>(value)];
    }
};

// A parameter's key with its C++ type T (int, double, bool or std::string): the table's spec is
// made from it (intParam(kKey, ...)) and the technique reads it with Params::get(kKey), so a key
// is spelled once, where it is declared, and read as the type the table gives it: a misspelled
// key does not compile, nor does reading a float as an int.
template <class T>
struct ParamKey {
    std::string_view key;
};
using IntKey = ParamKey<int>;
using FloatKey = ParamKey<double>;
using BoolKey = ParamKey<bool>;
using TextKey = ParamKey<std::string>;

constexpr ParamSpec intParam(IntKey key, int def, int min, int max, std::string_view doc) {
    return {key.key, ParamType::Int, double(def), double(min), double(max), {}, {}, doc};
}
constexpr ParamSpec floatParam(FloatKey key, double def, double min, double max,
                               std::string_view doc) {
    return {key.key, ParamType::Float, def, min, max, {}, {}, doc};
}
constexpr ParamSpec boolParam(BoolKey key, bool def, std::string_view doc) {
    return {key.key, ParamType::Bool, def ? 1.0 : 0.0, 0, 1, {}, {}, doc};
}

// The Enum parameter of KEY (static storage: the spec points at its names) with default DEF.
// Empty or repeated names fail to compile where the table is constexpr.
template <class E, std::size_t N>
constexpr ParamSpec enumParam(const EnumKey<E, N>& key, E def, std::string_view doc) {
    static_assert(N > 0, "an enum parameter needs choices");
    for (std::size_t i = 0; i < N; ++i) {
        if (key.names[i].empty() || key.names[i].find('|') != std::string_view::npos)
            throw "enumParam: a choice is empty or holds '|'";
        for (std::size_t j = 0; j < i; ++j)
            if (key.names[i] == key.names[j]) throw "enumParam: a choice is listed twice";
    }
    return {key.key,
            ParamType::Enum,
            0,
            0,
            0,
            std::span<const std::string_view>(key.names),
            key.name(def),
            doc};
}

// A free-form text value (e.g. a file path); DEF may be empty.
constexpr ParamSpec stringParam(TextKey key, std::string_view def, std::string_view doc) {
    return {key.key, ParamType::String, 0, 0, 0, {}, def, doc};
}

// The rows of A followed by those of B: a technique's table that includes rows declared where
// they are read (e.g. the environment lights' in renderer/techniques/environment_lights.h).
template <std::size_t N, std::size_t M>
constexpr std::array<ParamSpec, N + M> joinParams(const std::array<ParamSpec, N>& a,
                                                  const std::array<ParamSpec, M>& b) {
    std::array<ParamSpec, N + M> out{};
    for (std::size_t i = 0; i < N; ++i) out[i] = a[i];
    for (std::size_t i = 0; i < M; ++i) out[N + i] = b[i];
    return out;
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
    // A value by its key's name, for code that walks a table (uniforms, GL limits); a
    // technique reads its own keys with get().
    int getInt(std::string_view key) const;
    double getFloat(std::string_view key) const;
    bool getBool(std::string_view key) const;
    // An Enum's chosen name or a String's text.
    std::string getString(std::string_view key) const;
    // KEY's value as its table's type.
    template <class T>
    T get(ParamKey<T> key) const {
        if constexpr (std::is_same_v<T, int>)
            return getInt(key.key);
        else if constexpr (std::is_same_v<T, double>)
            return getFloat(key.key);
        else if constexpr (std::is_same_v<T, bool>)
            return getBool(key.key);
        else
            return getString(key.key);
    }
    // Enum KEY as its C++ enumerator.
    template <class E, std::size_t N>
    E getEnum(const EnumKey<E, N>& key) const {
        const std::string value = getString(key.key);
        for (std::size_t i = 0; i < N; ++i)
            if (key.names[i] == value) return static_cast<E>(i);
        throw std::logic_error("parameter '" + std::string(key.key) + "': '" + value +
                               "' is no name of its enum (the table's spec is not made from "
                               "this key)");
    }
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
