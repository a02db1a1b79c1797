// Typed, located JSON reading: the checks every scene key shares (types, finiteness, unknown
// keys), with one message format.
#include "renderer/scene/json_field.h"

#include <cfloat>
#include <cmath>

#include "renderer/core/did_you_mean.h"
#include "renderer/core/error.h"

namespace penumbra::scene {

namespace {
std::string located(const std::string& file, const std::string& key, const std::string& what) {
    return key.empty() ? file + ": " + what : file + ": " + key + ": " + what;
}
}  // namespace

void failAt(const std::string& file, const std::string& key, const std::string& what) {
    throw InputError(located(file, key, what));
}

UnknownKeyError::UnknownKeyError(const std::string& file, const std::string& parent,
                                 const std::string& name, const std::string& what)
    : InputError(located(file, parent, what)), key_(joinKey(parent, name)), what_(what) {}

std::string describeType(const nlohmann::json& value) {
    switch (value.type()) {
        case nlohmann::json::value_t::null:
            return "null";
        case nlohmann::json::value_t::object:
            return "an object";
        case nlohmann::json::value_t::array:
            return "an array";
        case nlohmann::json::value_t::string:
            return "a string";
        case nlohmann::json::value_t::boolean:
            return "a boolean";
        case nlohmann::json::value_t::number_integer:
        case nlohmann::json::value_t::number_unsigned:
        case nlohmann::json::value_t::number_float:
            return "a number";
        default:
            return "an unsupported value";
    }
}

std::string joinKey(const std::string& parent, std::string_view child) {
    if (parent.empty()) return std::string(child);
    return parent + "." + std::string(child);
}

void Field::expectObject(std::initializer_list<std::string_view> allowed) const {
    if (!value_->is_object()) fail("expected an object, got " + describeType(*value_));
    for (const auto& item : value_->items()) {
        bool known = false;
        for (std::string_view name : allowed) known = known || item.key() == name;
        if (known) continue;
        std::string list;
        for (std::string_view name : allowed) {
            if (!list.empty()) list += ", ";
            list += name;
        }
        const std::vector<std::string_view> names(allowed);
        const std::string near = nearestName(item.key(), names);
        throw UnknownKeyError(*file_, key_, item.key(),
                              "unknown key '" + item.key() + "' (" +
                                  (near.empty() ? "" : "did you mean '" + near + "'? ") +
                                  "allowed: " + list + ")");
    }
}

Field Field::member(std::string_view name) const {
    const auto it = value_->find(name);
    const nlohmann::json* child = it == value_->end() ? nullptr : &*it;
    return Field(child, joinKey(key_, name), *file_);
}

std::size_t Field::arraySize() const {
    if (!value_->is_array()) fail("expected an array, got " + describeType(*value_));
    return value_->size();
}

Field Field::element(std::size_t index) const {
    return Field(&(*value_)[index], joinKey(key_, std::to_string(index)), *file_);
}

double Field::number() const {
    if (!value_->is_number()) fail("expected a number, got " + describeType(*value_));
    const double v = value_->get<double>();
    if (!std::isfinite(v)) fail("expected a finite number");
    if (std::abs(v) > FLT_MAX) fail("number too large");
    return v;
}

long Field::integer(long lo, long hi) const {
    if (!value_->is_number()) fail("expected an integer, got " + describeType(*value_));
    const double v = value_->get<double>();
    if (!std::isfinite(v) || std::floor(v) != v) fail("expected an integer");
    if (v < static_cast<double>(lo) || v > static_cast<double>(hi))
        fail("must be in " + std::to_string(lo) + ".." + std::to_string(hi) + ", got " +
             value_->dump());
    return static_cast<long>(v);
}

std::string Field::string() const {
    if (!value_->is_string()) fail("expected a string, got " + describeType(*value_));
    return value_->get<std::string>();
}

double Field::numberAt(std::size_t index, std::size_t count) const {
    const std::string expected = "expected " + std::to_string(count) + " numbers";
    if (!value_->is_array()) fail(expected + ", got " + describeType(*value_));
    if (value_->size() != count)
        fail(expected + ", got " + std::to_string(value_->size()) + " elements");
    const nlohmann::json& v = (*value_)[index];
    if (!v.is_number())
        fail(expected + ", element " + std::to_string(index) + " is " + describeType(v));
    const double d = v.get<double>();
    if (!std::isfinite(d) || std::abs(d) > FLT_MAX)
        fail(expected + ", element " + std::to_string(index) + " is not finite");
    return d;
}

glm::vec2 Field::vec2() const {
    return {static_cast<float>(numberAt(0, 2)), static_cast<float>(numberAt(1, 2))};
}

glm::vec3 Field::vec3() const {
    return {static_cast<float>(numberAt(0, 3)), static_cast<float>(numberAt(1, 3)),
            static_cast<float>(numberAt(2, 3))};
}

std::vector<double> Field::numbers(std::size_t count) const {
    std::vector<double> out(count);
    for (std::size_t i = 0; i < count; ++i) out[i] = numberAt(i, count);
    return out;
}

bool Field::isNumberArray() const {
    if (!value_->is_array()) return false;
    for (const auto& v : *value_)
        if (!v.is_number()) return false;
    return true;
}

}  // namespace penumbra::scene
