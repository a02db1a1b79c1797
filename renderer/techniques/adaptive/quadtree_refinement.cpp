// `adaptive`'s quadtree refinement: the light-sample maps of new quadtree samples (rendered into
// their layers, or into a scratch map and copied, on the accumulation path), the light-centre
// reprojection view (4.1), and the choice of cells to split by the comparison counts, within the
// map budget (see adaptive.h).
#include "renderer/techniques/adaptive/adaptive.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include <glm/gtc/matrix_transform.hpp>

namespace penumbra::techniques::adaptive {

// Whether splitting CELL keeps the light's maps within max_maps.
bool Adaptive::fitsMapBudget(const adaptive::LightQuadtree& tree,
                             const adaptive::QuadtreeCell& cell) const {
    return int(tree.samples().size()) + tree.newSamples(cell) <= max_maps_;
}

// Metric "error": each cell's estimated error from its worse diagonal's COUNTS.
std::vector<double> Adaptive::cellErrors(const adaptive::LightQuadtree& tree,
                                         const std::vector<adaptive::QuadtreeCell>& cells,
                                         const std::vector<adaptive::CompareResult>& counts,
                                         double shadowed) {
    std::vector<double> errors;
    for (size_t i = 0, q = 0; i < cells.size(); ++i) {
        double disagreeing = 0;  // the worse diagonal
        for (size_t k = 0; k < tree.comparisons(cells[i]).size(); ++k, ++q)
            disagreeing = std::max(disagreeing, counts[q].pixels);
        const double share = std::ldexp(1.0, -(tree.linear() ? 1 : 2) * cells[i].depth);
        errors.push_back(adaptive::cellError(share, disagreeing, shadowed));
    }
    return errors;
}

// Metric "error": splits the CELLS whose estimated error (from COUNTS, in comparisons()
// order, over SHADOWED pixels) BUDGET chooses, within the map budget; returns the children.
std::vector<adaptive::QuadtreeCell> Adaptive::splitByError(
    adaptive::LightQuadtree& tree, const std::vector<adaptive::QuadtreeCell>& cells,
    const std::vector<adaptive::CompareResult>& counts, double shadowed,
    adaptive::ErrorBudget& budget, bool& budget_hit) const {
    const std::vector<double> errors = cellErrors(tree, cells, counts, shadowed);
    std::vector<adaptive::QuadtreeCell> next;
    for (size_t i : budget.choose(errors)) {
        if (!fitsMapBudget(tree, cells[i])) {
            budget_hit = true;
            budget.refused(errors[i]);
            continue;
        }
        for (const auto& child : tree.split(cells[i])) next.push_back(child);
    }
    return next;
}

// The bits path's splits, each in the tiles around where its cell disagreed.
std::vector<adaptive::QuadtreeCell> Adaptive::splitInTiles(
    adaptive::LightQuadtree& tree, const std::vector<adaptive::QuadtreeCell>& cells,
    const std::vector<size_t>& chosen, const std::vector<std::vector<std::uint32_t>>& where,
    const std::function<void(size_t)>& refused, bool& budget_hit) {
    std::vector<adaptive::QuadtreeCell> next;
    std::vector<adaptive::TileMask> next_tiles;
    std::vector<bool> split(cells.size(), false);
    for (size_t i : chosen) {
        const adaptive::TileMask& live = cell_tiles_[i];
        adaptive::TileMask tiles = live;
        if (tiles_->count() > 1) {
            tiles = tiles_->around(where[i], tile_of_, live);
            for (size_t t = 0; t < tiles.size(); ++t) tiles[t] |= horizon_tiles_[t] & live[t];
        }
        const bool somewhere = std::find(tiles.begin(), tiles.end(), 1) != tiles.end();
        if (!somewhere || !fitsMapBudget(tree, cells[i])) {
            budget_hit = budget_hit || somewhere;  // the map budget refused it
            refused(i);
            continue;
        }
        split[i] = true;
        adaptive::TileMask rest = live;  // where the cell stays a leaf
        for (size_t t = 0; t < rest.size(); ++t) rest[t] &= std::uint8_t(!tiles[t]);
        tiled_leaves_.push_back({cells[i], std::move(rest)});
        for (const auto& child : tree.split(cells[i])) {
            next.push_back(child);
            next_tiles.push_back(tiles);
            view_tiles_.resize(tree.samples().size(), adaptive::TileMask(tiles.size(), 0));
            for (auto [a, b] : tree.comparisons(child))  // its corners are tested there
                for (size_t t = 0; t < tiles.size(); ++t) {
                    view_tiles_[size_t(a)][t] |= tiles[t];
                    view_tiles_[size_t(b)][t] |= tiles[t];
                }
        }
    }
    for (size_t i = 0; i < cells.size(); ++i)
        if (!split[i]) tiled_leaves_.push_back({cells[i], cell_tiles_[i]});
    cell_tiles_ = std::move(next_tiles);
    return next;
}

// Splits the CELLS whose comparisons (COUNTS, in comparisons() order) fail the metric, most
// disagreeing first so that the map budget goes where it matters; returns their children.
std::vector<adaptive::QuadtreeCell> Adaptive::splitCells(
    adaptive::LightQuadtree& tree, const std::vector<adaptive::QuadtreeCell>& cells,
    const std::vector<adaptive::CompareResult>& counts, double area, bool& budget_hit) const {
    const double tile_area = double(compare_.tile_size) * double(compare_.tile_size);
    std::vector<std::pair<double, size_t>> refine;
    for (size_t i = 0, q = 0; i < cells.size(); ++i) {
        double worst = 0;
        bool split = false;
        for (size_t k = 0; k < tree.comparisons(cells[i]).size(); ++k, ++q) {
            const auto& r = counts[q];
            worst = std::max(worst, r.pixels);
            split |= compare_.tile_size > 0
                         ? r.max_tile > 0 && r.max_tile / tile_area >= tile_epsilon_
                         : r.pixels > 0 && r.pixels / area >= epsilon_;
        }
        if (split) refine.push_back({worst, i});
    }
    std::stable_sort(refine.begin(), refine.end(),
                     [](const auto& a, const auto& b) { return a.first > b.first; });
    std::vector<adaptive::QuadtreeCell> next;
    for (const auto& [worst, i] : refine) {
        if (!fitsMapBudget(tree, cells[i])) {
            budget_hit = true;
            continue;
        }
        for (const auto& child : tree.split(cells[i])) next.push_back(child);
    }
    return next;
}

// A perspective view from the light's centre along its axis, covering every caster as
// seen from there, and every receiver behind them (section 4.1's reprojection target).
passes::CameraMatrices Adaptive::lightCentreView(const frame::FrameContext& ctx) const {
    const scene::RectLight& light = ctx.currentLight();
    const passes::SampleView v = passes::makeSampleView(
        light, light.position, ctx.gpu.casterBoxes(), 1.0f, settings_.map_size);
    const float n = v.forward.w;
    const float l = v.frustum.x, b = v.frustum.y;
    const float r = l + 1.0f / v.frustum.z, t = b + 1.0f / v.frustum.w;
    passes::CameraMatrices m;
    m.position = light.position;
    m.view = glm::lookAt(light.position, light.position + light.forward(), light.upAxis());
    m.projection = glm::frustum(l * n, r * n, b * n, t * n, n, n * 1e4f);
    return m;
}

// Renders the samples without a map yet into their layers of maps_ (one pass per level).
void Adaptive::renderNewMaps(frame::FrameContext& ctx, const adaptive::LightQuadtree& tree,
                             int level) {
    const scene::RectLight& light = ctx.currentLight();
    const auto corners = light.corners();
    const int first = static_cast<int>(views_.size());
    for (size_t i = views_.size(); i < tree.samples().size(); ++i) {
        const glm::vec2 uv = tree.samples()[i].uv;
        glm::vec3 p =
            corners[0] + (corners[1] - corners[0]) * uv.x + (corners[3] - corners[0]) * uv.y;
        views_.push_back(passes::makeSampleView(light, p, ctx.gpu.casterBoxes(), 1.0f, map_size_));
    }
    const int n = static_cast<int>(views_.size());
    if (first == n) return;
    if (litPath()) {
        views_buffer_.upload(views_);
        view_tiles_.resize(size_t(n), tiles_->all());  // the root's corners: everywhere
        lit_bits_->setTestedTiles(*tiles_, view_tiles_);
        ctx.pass("adaptive_maps[" + std::to_string(level) + "]",
                 [&] { renderAndTest(ctx, first, n); });
        return;
    }
    reserveMaps(first, n);
    if (accumulate_path_) {
        // Each map is added with its unnormalised weight as soon as it exists (3.4.1); the
        // G-buffer is the camera depth pre-pass, so only visible receivers accumulate.
        for (int k = first; k < n; ++k) {
            const float w = sampleWeight(tree, tree.samples()[size_t(k)].depth);
            views_[size_t(k)].origin.w = w;
            views_[size_t(k)].depth.y = w;
        }
        views_buffer_.upload(views_);
        ctx.pass("adaptive_maps_accumulate[" + std::to_string(level) + "]", [&] {
            for (int k = first; k < n; ++k) {
                scratch_->render(ctx.gpu, k, 1);
                copyToMaps(k, 1);
                ctx.bindOutput();
                addToVisibility(ctx, *scratch_, k, 1);
            }
        });
        return;
    }
    views_buffer_.upload(views_);
    // Straight into their layers (layer = view index), kScratchLayers per draw.
    ctx.pass("adaptive_maps[" + std::to_string(level) + "]", [&] {
        for (int base = first; base < n; base += kScratchLayers)
            maps_->render(ctx.gpu, base, std::min(kScratchLayers, n - base), base);
    });
}

// The lit path: renders views FIRST..N-1 into scratch_ kTestBatch at a time and sets their
// shadow bits.
void Adaptive::renderAndTest(frame::FrameContext& ctx, int first, int n) {
    const passes::GBuffer& receivers = ctx.gbuffer;
    for (int base = first; base < n; base += scratch_->layers()) {
        const int count = std::min(scratch_->layers(), n - base);
        scratch_->render(ctx.gpu, base, count, 0);  // clears only the COUNT layers drawn
        lit_bits_->test(receivers, *scratch_, base, count, ctx.currentLight(), compare_);
    }
}

// Grows maps_ to at least N layers (twice its layers, at least 25, at most max_maps), keeping
// its first FILLED maps: its memory follows the refinement a scene reaches, not max_maps.
void Adaptive::reserveMaps(int filled, int n) {
    if (maps_ && maps_->layers() >= n) return;
    const int layers = std::min(max_maps_, std::max({n, maps_ ? 2 * maps_->layers() : 0, 25}));
    auto grown = std::make_unique<passes::ShadowMapBatch>(map_size_, layers, vertex_layer_);
    if (maps_ && filled > 0)
        glCopyImageSubData(maps_->depth().id(), GL_TEXTURE_2D_ARRAY, 0, 0, 0, 0,
                           grown->depth().id(), GL_TEXTURE_2D_ARRAY, 0, 0, 0, 0, map_size_,
                           map_size_, filled);
    maps_ = std::move(grown);
}

// Copies scratch layers 0..COUNT-1 to maps_ layers BASE.. (layer = view index there).
void Adaptive::copyToMaps(int base, int count) {
    glCopyImageSubData(scratch_->depth().id(), GL_TEXTURE_2D_ARRAY, 0, 0, 0, 0, maps_->depth().id(),
                       GL_TEXTURE_2D_ARRAY, 0, 0, 0, base, map_size_, map_size_, count);
}

}  // namespace penumbra::techniques::adaptive
