// The render job's input checks: see render_job_checks.h.
#include "renderer/app/render_job_checks.h"

#include <algorithm>
#include <cctype>
#include <vector>

#include "renderer/core/did_you_mean.h"
#include "renderer/core/error.h"
#include "renderer/core/json_bounds.h"
#include "renderer/scene/overrides.h"

namespace penumbra::app {

std::string unknownTechniqueMessage(const std::string& name) {
    std::vector<std::string> names;
    std::string known;
    for (const auto& t : techniques::allTechniques()) {
        names.emplace_back(t.name);
        known += (known.empty() ? "" : ", ") + names.back();
    }
    const std::string near = nearestName(name, names);
    return "unknown technique '" + name + "' (" +
           (near.empty() ? "" : "did you mean '" + near + "'? ") + "known: " + known + ")";
}

const techniques::TechniqueInfo& findTechniqueOrThrow(const scene::Scene& s,
                                                      const RenderRequest& req) {
    std::string name = s.technique.value("name", std::string("hard"));
    if (const auto* info = techniques::findTechnique(name)) return *info;
    std::string where = req.technique ? "--technique" : s.path.string() + ": technique.name";
    throw InputError(where + ": " + unknownTechniqueMessage(quoteText(name)));
}

Params resolveFor(const techniques::TechniqueInfo& info, const scene::Scene& s) {
    return resolveParams(info.params, s.technique, s.path.string() + ": technique");
}

void checkTechniqueOverrides(const techniques::TechniqueInfo& info, const RenderRequest& req) {
    constexpr std::string_view kPrefix = "technique.";
    for (const scene::Override& o : req.overrides) {
        if (o.key.rfind(kPrefix, 0) != 0 || o.key == "technique.name") continue;
        nlohmann::json block = {{"name", std::string(info.name)},
                                {o.key.substr(kPrefix.size()), scene::parseOverrideValue(o)}};
        (void)resolveParams(info.params, block, "-D technique");
    }
}

void checkGlLimits(const scene::Scene& s, const techniques::TechniqueInfo& technique,
                   const Params& params, const gl::ContextInfo& info) {
    const std::string where = s.path.string() + ": ";
    const int max = std::min(info.max_texture_size, info.max_renderbuffer_size);
    if (s.image.width > max)
        throw InputError(where + "image.width: " + std::to_string(s.image.width) +
                         " exceeds this GL's limit of " + std::to_string(max));
    if (s.image.height > max)
        throw InputError(where + "image.height: " + std::to_string(s.image.height) +
                         " exceeds this GL's limit of " + std::to_string(max));
    for (const ParamSpec& spec : technique.params) {
        if (spec.limited_by != GlLimit::MaxTextureSize) continue;
        const int value = params.getInt(spec.key);
        if (value > info.max_texture_size)
            throw InputError(where + "technique." + std::string(spec.key) + ": " +
                             std::to_string(value) + " exceeds this GL's texture limit of " +
                             std::to_string(info.max_texture_size));
    }
    if (s.lights.size() > static_cast<size_t>(info.max_array_layers))
        throw InputError(where + "lights: more lights than this GL's array layers allow");
}

}  // namespace penumbra::app
