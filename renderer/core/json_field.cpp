// The one typed-JSON checker: types, ranges, choices, finiteness and unknown keys, with one
// message style "<file>: <key>: expected <what>, got <value>" (see json_field.h).
#include "renderer/core/json_field.h"

#include <cfloat>
#include <cmath>

#include "renderer/core/did_you_mean.h"
#include "renderer/core/error.h"
#include "renderer/core/json_bounds.h"

namespace penumbra {

namespace {
std::string located(const std::string& file, const std::string& key, const std::string& what) {
    std::string out = file;
    if (!key.empty()) out += (out.empty() ? "" : ": ") + key;
    return out.empty() ? what : out + ": " + what;
}

std::string joinList(std::span<const std::string_view> names) {
    std::string list;
    for (std::string_view name : names) list += (list.empty() ? "" : ", ") + std::string(name);
    return list;
}

bool fitsFloat(double v) {
    return std::isfinite(v) && std::abs(v) <= FLT_MAX;
}
}  // namespace

void failAt(const std::string& file, const std::string& key, const std::string& what) {
    throw InputError(located(file, key, what));
}

void failExpected(const std::string& file, const std::string& key, std::string_view what,
                  const nlohmann::json& got) {
    failAt(file, key, "expected " + std::string(what) + ", got " + quoteJson(got));
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

std::string formatNumber(double v) {
    nlohmann::json j = v;
    if (v == std::floor(v) && std::fabs(v) < 1e15) j = static_cast<long long>(v);
    return j.dump();
}

void Field::expected(std::string_view what) const {
    if (!value_) fail("expected " + std::string(what) + ", got nothing");
    failExpected(*file_, key_, what, *value_);
}

void Field::expectObject() const {
    if (!value_ || !value_->is_object()) expected("an object");
}

void Field::expectObject(std::initializer_list<std::string_view> allowed) const {
    expectObject();
    const std::vector<std::string_view> names(allowed);
    for (const auto& item : value_->items()) {
        bool known = false;
        for (std::string_view name : allowed) known = known || item.key() == name;
        if (known) continue;
        const std::string near = nearestName(item.key(), names);
        throw UnknownKeyError(*file_, key_, item.key(),
                              "unknown key '" + item.key() + "' (" +
                                  (near.empty() ? "" : "did you mean '" + near + "'? ") +
                                  "allowed: " + joinList(names) + ")");
    }
}

Field Field::member(std::string_view name) const {
    const auto it = value_->find(name);
    const nlohmann::json* child = it == value_->end() ? nullptr : &*it;
    return Field(child, joinKey(key_, name), *file_);
}

std::size_t Field::arraySize() const {
    if (!value_ || !value_->is_array()) expected("an array");
    return value_->size();
}

Field Field::element(std::size_t index) const {
    return Field(&(*value_)[index], joinKey(key_, std::to_string(index)), *file_);
}

double Field::number() const {
    if (!value_->is_number()) expected("a number");
    const double v = value_->get<double>();
    if (!fitsFloat(v)) expected("a number within +-3.4e38");
    return v;
}

double Field::number(double lo, double hi) const {
    const std::string what = "a number in " + formatNumber(lo) + ".." + formatNumber(hi);
    if (!value_->is_number()) expected(what);
    const double v = value_->get<double>();
    if (!std::isfinite(v) || v < lo || v > hi) expected(what);
    return v;
}

long Field::integer(long lo, long hi) const {
    const std::string what = "an integer in " + std::to_string(lo) + ".." + std::to_string(hi);
    if (!value_->is_number()) expected(what);
    const double v = value_->get<double>();
    if (!std::isfinite(v) || std::floor(v) != v) expected(what);
    if (v < static_cast<double>(lo) || v > static_cast<double>(hi)) expected(what);
    return static_cast<long>(v);
}

long Field::strictInteger(long lo, long hi) const {
    if (!value_->is_number_integer())
        expected("an integer in " + std::to_string(lo) + ".." + std::to_string(hi));
    return integer(lo, hi);  // the range, with the same message
}

bool Field::boolean() const {
    if (!value_->is_boolean()) expected("true or false");
    return value_->get<bool>();
}

std::string Field::string() const {
    if (!value_->is_string()) expected("a string");
    return value_->get<std::string>();
}

std::string Field::choice(std::span<const std::string_view> choices) const {
    if (value_->is_string())
        for (std::string_view c : choices)
            if (c == value_->get_ref<const std::string&>()) return std::string(c);
    expected("one of " + joinList(choices));
}

double Field::numberAt(std::size_t index, std::size_t count) const {
    const std::string what = std::to_string(count) + " numbers";
    if (!value_->is_array() || value_->size() != count) expected(what);
    const nlohmann::json& v = (*value_)[index];
    if (!v.is_number()) expected(what);
    const double d = v.get<double>();
    if (!fitsFloat(d)) expected(what + " within +-3.4e38");
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

}  // namespace penumbra
