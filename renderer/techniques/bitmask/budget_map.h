// `bitmask`'s budget map from an image (Schwarz & Stamminger 2008, section 4.2: a budget map
// varies b_mo across the screen): the first channel of a PNG or EXR, stretched over the image,
// whose value v in [0, 1] gives b_mo = budget_edge + v (budget - budget_edge) per pixel.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "renderer/gl/handles.h"

namespace penumbra::techniques::bitmask {

constexpr int kMaxBudgetMapSize = 4096;  // width and height limit, pixels

struct BudgetMap {
    int width = 0, height = 0;
    std::vector<float> values;  // rows bottom first (GL's order), clamped to [0, 1]
};

// Reads FILE (relative to the folder of SCENE_FILE unless absolute). Throws
// InputError("technique.budget_map: <path>: <what is wrong>").
BudgetMap readBudgetMap(const std::filesystem::path& scene_file, const std::string& file);

// MAP as an R32F texture, bilinear, clamped to its edges.
gl::Texture uploadBudgetMap(const BudgetMap& map);

}  // namespace penumbra::techniques::bitmask
