// Command-line changes to a scene document before validation: -t NAME (technique) and
// -D KEY=VALUE (any value by dotted key). Errors name the flag: "-D lights.3.size: ...".
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "renderer/scene/scene_source.h"

namespace penumbra::scene {

// -t NAME: when NAME differs from DOC's technique.name, the technique block becomes
// {"name": NAME} (its other keys were parameters of another technique).
void applyTechniqueOption(nlohmann::json& doc, const std::optional<std::string>& technique);

// VALUE of -D KEY=VALUE: JSON, or the plain string when it is not JSON (a bare word).
nlohmann::json parseOverrideValue(const Override& override_);

// Sets every override in order. Missing object members along a key are created; array indices
// must exist.
void applyOverrides(nlohmann::json& doc, const std::vector<Override>& overrides);

}  // namespace penumbra::scene
