// `bitmask`'s budget map: see budget_map.h.
#include "renderer/techniques/bitmask/budget_map.h"

#include <algorithm>

#include "renderer/scene/image_file.h"

namespace penumbra::techniques::bitmask {

BudgetMap readBudgetMap(const std::filesystem::path& scene_file, const std::string& file) {
    std::filesystem::path path(file);
    if (path.is_relative()) path = scene_file.parent_path() / path;
    const scene::FloatImage image =
        scene::readFloatImage(path, "technique.budget_map: " + path.string(), {".png", ".exr"},
                              "a .png or .exr image", kMaxBudgetMapSize, 1);
    BudgetMap map;
    map.width = image.width;
    map.height = image.height;
    map.values = image.pixels;
    for (float& v : map.values) v = std::clamp(v, 0.0f, 1.0f);
    const auto row = static_cast<std::ptrdiff_t>(image.width);
    for (std::ptrdiff_t y = 0; y < image.height / 2; ++y)  // top row first -> bottom row first
        std::swap_ranges(map.values.begin() + y * row, map.values.begin() + (y + 1) * row,
                         map.values.end() - (y + 1) * row);
    return map;
}

gl::Texture uploadBudgetMap(const BudgetMap& map) {
    gl::Texture t = gl::createTexture2D(GL_R32F, map.width, map.height, "bitmask budget map");
    glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(t.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTextureSubImage2D(t.id(), 0, 0, 0, map.width, map.height, GL_RED, GL_FLOAT,
                        map.values.data());
    return t;
}

}  // namespace penumbra::techniques::bitmask
