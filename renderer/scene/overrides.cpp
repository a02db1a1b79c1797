// -t and -D applied to the scene document, in that order, with errors that name the flag and
// its key ("-D lights.3.size: index 3 out of range ...").
#include "renderer/scene/overrides.h"

#include "renderer/core/error.h"
#include "renderer/core/json_bounds.h"
#include "renderer/core/json_field.h"
#include "renderer/scene/dotted_key.h"

namespace penumbra::scene {
namespace {

[[noreturn]] void failOverride(const Override& o, const std::string& what) {
    throw InputError("-D " + o.key + ": " + what);
}

void setAt(nlohmann::json& doc, const Override& o, nlohmann::json value) {
    const auto parts = splitDottedKey(o.key);
    if (!parts) failOverride(o, "malformed key (expected names separated by single dots)");
    nlohmann::json* current = &doc;
    std::string where;  // dotted key of *current
    for (std::size_t i = 0; i < parts->size(); ++i) {
        const std::string& part = (*parts)[i];
        const bool last = i + 1 == parts->size();
        if (current->is_array()) {
            const auto index = arrayIndex(part);
            if (!index) failOverride(o, where + " is an array; '" + part + "' is not an index");
            if (*index >= current->size())
                failOverride(o, "index " + part + " out of range (" + where + " has " +
                                    std::to_string(current->size()) +
                                    (current->size() == 1 ? " element)" : " elements)"));
            current = &(*current)[*index];
        } else if (current->is_object()) {
            if (!current->contains(part)) {
                if (!last && arrayIndex((*parts)[i + 1]))
                    failOverride(o, joinKey(where, part) +
                                        " does not exist, so it has no element " + (*parts)[i + 1]);
                (*current)[part] = last ? std::move(value) : nlohmann::json::object();
                if (last) return;
            }
            current = &(*current)[part];
        } else {
            failOverride(o, where + " is " + describeType(*current) +
                                ", not an object or array, so it has no '" + part + "'");
        }
        where = joinKey(where, part);
    }
    *current = std::move(value);
}

}  // namespace

void applyTechniqueOption(nlohmann::json& doc, const std::optional<std::string>& technique) {
    if (!technique) return;
    const auto it = doc.find("technique");
    if (it != doc.end() && it->is_object()) {
        const nlohmann::json& block = *it;
        if (block.contains("name") && block["name"] == nlohmann::json(*technique)) return;
    }
    doc["technique"] = nlohmann::json{{"name", *technique}};
}

nlohmann::json parseOverrideValue(const Override& o) {
    std::string why;
    if (auto value = parseJsonBounded(o.value, "-D " + o.key, &why)) return std::move(*value);
    // Text that starts like JSON structure or a JSON string was meant as JSON: say why it is not.
    const std::size_t first = o.value.find_first_not_of(" \t\r\n");
    if (first != std::string::npos &&
        (o.value[first] == '[' || o.value[first] == '{' || o.value[first] == '"'))
        failOverride(o, "value is not valid JSON: " + why);
    return o.value;  // a bare word: the string itself
}

void applyOverrides(nlohmann::json& doc, const std::vector<Override>& overrides) {
    for (const Override& o : overrides) setAt(doc, o, parseOverrideValue(o));
}

}  // namespace penumbra::scene
