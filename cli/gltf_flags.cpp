// The glTF scene flags: see gltf_flags.h.
#include "cli/gltf_flags.h"

#include <string>

#include "renderer/core/json_bounds.h"

namespace penumbra::cli {
namespace {

// One side of --light-size: a number in [kMinLightSize, kMaxLightSize] metres.
float lightSide(const ArgCursor& c, const std::string& text) {
    const double v = parseDouble(c, "--light-size", text);
    if (!(v >= kMinLightSize && v <= kMaxLightSize))
        c.fail("--light-size: '" + quoteText(text) + "' is out of range [1e-6, 1e6] metres");
    return static_cast<float>(v);
}

}  // namespace

bool parseGltfSceneFlag(ArgCursor& c, scene::GltfSceneOptions& options) {
    if (c.flag("", "--no-floor")) {
        options.floor = false;
        return true;
    }
    const auto v = c.option("", "--light-size");
    if (!v) return false;
    const std::size_t x = v->find('x');
    const float w = lightSide(c, v->substr(0, x));
    const float h = x == std::string::npos ? w : lightSide(c, v->substr(x + 1));
    options.light_size = glm::vec2(w, h);
    return true;
}

bool gltfSceneFlagsGiven(const scene::GltfSceneOptions& options) {
    return options.light_size || !options.floor;
}

}  // namespace penumbra::cli
