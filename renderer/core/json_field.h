// The one typed-JSON checker: reads a typed value at a key of a document, every error a one-line
// InputError "<file>: <key>: expected <what>, got <the value, quoted to 80 characters>".
#pragma once

#include <cstddef>
#include <initializer_list>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "renderer/core/error.h"

namespace penumbra {

// Throws InputError("<file>: <key>: <what>"); an empty FILE or KEY drops its part.
[[noreturn]] void failAt(const std::string& file, const std::string& key, const std::string& what);

// Throws InputError("<file>: <key>: expected <what>, got <GOT quoted>"): the message style of
// every typed check.
[[noreturn]] void failExpected(const std::string& file, const std::string& key,
                               std::string_view what, const nlohmann::json& got);

// An unknown key (the message failAt gives), with its full dotted KEY, so that the loader can
// blame the -D flag that created it instead of the file.
class UnknownKeyError : public InputError {
public:
    UnknownKeyError(const std::string& file, const std::string& parent, const std::string& name,
                    const std::string& what);
    const std::string& key() const { return key_; }         // "technique.x", "lights.0.sise"
    const std::string& what_only() const { return what_; }  // the message after the key

private:
    std::string key_, what_;
};

// The JSON type of VALUE in words ("a string", "an array", ...).
std::string describeType(const nlohmann::json& value);

// A JSON value (possibly absent) at a dotted key of a file (FILE may be empty, then KEY alone
// locates it, e.g. "s.json: technique").
class Field {
public:
    Field(const nlohmann::json* value, std::string key, const std::string& file)
        : value_(value), key_(std::move(key)), file_(&file) {}

    bool present() const { return value_ != nullptr; }
    const nlohmann::json& json() const { return *value_; }
    const std::string& key() const { return key_; }
    const std::string& file() const { return *file_; }
    [[noreturn]] void fail(const std::string& what) const { failAt(*file_, key_, what); }
    // "expected WHAT, got <this value>".
    [[noreturn]] void expected(std::string_view what) const;

    // Requires an object whose keys are all in ALLOWED; names the unknown key and the allowed ones.
    void expectObject(std::initializer_list<std::string_view> allowed) const;
    void expectObject() const;  // any keys
    // The member NAME of this object (absent when missing).
    Field member(std::string_view name) const;
    // Requires an array; returns its size.
    std::size_t arraySize() const;
    Field element(std::size_t index) const;

    double number() const;  // a finite number that fits a float
    double numberOr(double fallback) const { return present() ? number() : fallback; }
    double number(double lo, double hi) const;  // a finite number in [lo, hi]
    // An integer in [lo, hi]; a float with an integral value counts (animation interpolates).
    long integer(long lo, long hi) const;
    // A JSON integer (no fraction part, not 2.0) in [lo, hi]: glTF's indices and counts.
    long strictInteger(long lo, long hi) const;
    bool boolean() const;
    std::string string() const;
    // A string among CHOICES.
    std::string choice(std::span<const std::string_view> choices) const;
    glm::vec2 vec2() const;
    glm::vec3 vec3() const;
    glm::vec3 vec3Or(glm::vec3 fallback) const { return present() ? vec3() : fallback; }
    // Exactly COUNT finite numbers.
    std::vector<double> numbers(std::size_t count) const;
    // True when this is an array of numbers (any length).
    bool isNumberArray() const;

private:
    double numberAt(std::size_t index, std::size_t count) const;

    const nlohmann::json* value_;
    std::string key_;
    const std::string* file_;
};

// "a.b" + "c" -> "a.b.c"; "" + "c" -> "c".
std::string joinKey(const std::string& parent, std::string_view child);

// A number as the messages write it: 32, 0.5, -0.1.
std::string formatNumber(double v);

}  // namespace penumbra
