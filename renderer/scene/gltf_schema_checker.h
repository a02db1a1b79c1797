// The located checks gltf_schema.cpp runs over a glTF's JSON: optional members, arrays of
// objects, indices and references, each failing with the typed checker's message (json_field.h).
#pragma once

#include <climits>
#include <cstddef>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "renderer/core/json_field.h"

namespace penumbra::scene {

class SchemaChecker {
public:
    explicit SchemaChecker(const std::string& label) : label_(label) {}

    [[noreturn]] void fail(const std::string& key, const std::string& what) const {
        failAt(label_, key, what);
    }

    // The member NAME of OBJ, or nullptr when absent.
    static const nlohmann::json* find(const nlohmann::json& obj, std::string_view name) {
        const auto it = obj.find(name);
        return it == obj.end() ? nullptr : &*it;
    }

    Field at(const nlohmann::json& v, const std::string& key) const {
        return Field(&v, key, label_);
    }
    void object(const nlohmann::json& v, const std::string& key) const {
        at(v, key).expectObject();
    }
    void string(const nlohmann::json& v, const std::string& key) const {
        (void)at(v, key).string();
    }
    void boolean(const nlohmann::json& v, const std::string& key) const {
        (void)at(v, key).boolean();
    }
    // A non-negative integer that fits an int (indices, offsets, lengths, counts).
    long index(const nlohmann::json& v, const std::string& key, long min = 0) const {
        return at(v, key).strictInteger(min, INT_MAX);
    }
    void numbers(const nlohmann::json& v, const std::string& key, std::size_t count) const {
        (void)at(v, key).numbers(count);
    }
    // Calls FN(element, key) for each element of OBJ[NAME], which must be an array of objects.
    template <typename Fn>
    void eachObject(const nlohmann::json& obj, const std::string& key, std::string_view name,
                    Fn fn) const {
        const nlohmann::json* array = find(obj, name);
        if (!array) return;
        const std::string array_key = joinKey(key, name);
        const std::size_t size = at(*array, array_key).arraySize();
        for (std::size_t i = 0; i < size; ++i) {
            const std::string element_key = joinKey(array_key, std::to_string(i));
            object((*array)[i], element_key);
            fn((*array)[i], element_key);
        }
    }
    // Optional member checks.
    void optIndex(const nlohmann::json& obj, const std::string& key, std::string_view name,
                  long min = 0) const {
        if (const nlohmann::json* v = find(obj, name)) index(*v, joinKey(key, name), min);
    }
    void optIndexArray(const nlohmann::json& obj, const std::string& key,
                       std::string_view name) const {
        const nlohmann::json* v = find(obj, name);
        if (!v) return;
        const std::string k = joinKey(key, name);
        const std::size_t size = at(*v, k).arraySize();
        for (std::size_t i = 0; i < size; ++i) index((*v)[i], joinKey(k, std::to_string(i)));
    }
    void optString(const nlohmann::json& obj, const std::string& key, std::string_view name) const {
        if (const nlohmann::json* v = find(obj, name)) string(*v, joinKey(key, name));
    }
    void optObject(const nlohmann::json& obj, const std::string& key, std::string_view name) const {
        if (const nlohmann::json* v = find(obj, name)) object(*v, joinKey(key, name));
    }
    void optNumbers(const nlohmann::json& obj, const std::string& key, std::string_view name,
                    std::size_t count) const {
        if (const nlohmann::json* v = find(obj, name)) numbers(*v, joinKey(key, name), count);
    }
    // An index into an array of COUNT WHATs ("accessor").
    void reference(const nlohmann::json& v, const std::string& key, std::size_t count,
                   const char* what) const {
        const long i = index(v, key);
        if (static_cast<std::size_t>(i) >= count)
            fail(key, std::string(what) + " " + std::to_string(i) + " does not exist");
    }
    // An object whose members are all indices (primitive attributes).
    void indexMap(const nlohmann::json& v, const std::string& key) const {
        object(v, key);
        for (const auto& item : v.items()) index(item.value(), joinKey(key, item.key()));
    }

private:
    const std::string& label_;
};

}  // namespace penumbra::scene
