// Typed reading of one JSON value that knows where it came from: every error it raises is a
// one-line InputError "<file>: <dotted key>: <what is wrong>".
#pragma once

#include <cstddef>
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "renderer/core/error.h"

namespace penumbra::scene {

// Throws InputError("<file>: <key>: <what>"), or "<file>: <what>" when KEY is empty.
[[noreturn]] void failAt(const std::string& file, const std::string& key, const std::string& what);

// An unknown key (the message failAt gives), with its full dotted KEY, so that the loader can
// blame the -D flag that created it instead of the file.
class UnknownKeyError : public InputError {
public:
    UnknownKeyError(const std::string& file, const std::string& parent, const std::string& name,
                    const std::string& what);
    const std::string& key() const { return key_; }    // "technique.x", "lights.0.sise"
    const std::string& what_only() const { return what_; }  // the message after the key

private:
    std::string key_, what_;
};

// The JSON type of VALUE in words ("a string", "an array", ...), for "expected X, got Y".
std::string describeType(const nlohmann::json& value);

// A JSON value (possibly absent) at a dotted key of a file.
class Field {
public:
    Field(const nlohmann::json* value, std::string key, const std::string& file)
        : value_(value), key_(std::move(key)), file_(&file) {}

    bool present() const { return value_ != nullptr; }
    const nlohmann::json& json() const { return *value_; }
    const std::string& key() const { return key_; }
    const std::string& file() const { return *file_; }
    [[noreturn]] void fail(const std::string& what) const { failAt(*file_, key_, what); }

    // Requires an object whose keys are all in ALLOWED; names the unknown key and the allowed ones.
    void expectObject(std::initializer_list<std::string_view> allowed) const;
    // The member NAME of this object (absent when missing).
    Field member(std::string_view name) const;
    // Requires an array; returns its size.
    std::size_t arraySize() const;
    Field element(std::size_t index) const;

    double number() const;  // a finite number that fits a float
    double numberOr(double fallback) const { return present() ? number() : fallback; }
    // An integer in [lo, hi]; a float with an integral value counts (animation interpolates).
    long integer(long lo, long hi) const;
    std::string string() const;
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

}  // namespace penumbra::scene
