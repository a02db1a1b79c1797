// `adaptive`'s default refinement (metric "error" on hard tests): the bits of which of the level's
// corner maps shadow each pixel (LitBits' or one pass over the array), the CPU's comparison of
// every cell's diagonals on them and the error budget's choice of cells to split (adaptive.h).
#include <chrono>
#include <cmath>
#include <string>

#include "renderer/techniques/adaptive/adaptive.h"

namespace penumbra::techniques::adaptive {

std::vector<QuadtreeCell> Adaptive::refineByBits(frame::FrameContext& ctx, LightQuadtree& tree,
                                                 const std::vector<QuadtreeCell>& cells,
                                                 const passes::GBuffer& receivers, int level,
                                                 ErrorBudget& sum_budget,
                                                 std::optional<PixelErrorBudget>& budget,
                                                 Refinement& r) {
    // Each corner map of the level gets one slot, shared by every cell it is a corner of (the
    // lit path's bits hold every view: slot = view).
    std::vector<int> views, slot(tree.samples().size(), -1);
    auto slotOf = [&](int view) {
        if (litPath()) return view;
        if (slot[size_t(view)] < 0) {
            slot[size_t(view)] = int(views.size());
            views.push_back(view);
        }
        return slot[size_t(view)];
    };
    std::vector<std::vector<std::pair<int, int>>> pairs(cells.size());
    for (size_t i = 0; i < cells.size(); ++i)
        for (auto [a, b] : tree.comparisons(cells[i])) pairs[i].push_back({slotOf(a), slotOf(b)});
    std::vector<int> corners;
    if (level == 0)
        for (int v : tree.linear() ? std::vector{0, 1} : std::vector{0, 1, 2, 3})
            corners.push_back(slotOf(v));
    ShadowBits bits;
    ctx.pass("adaptive_compare[" + std::to_string(level) + "]", [&] {
        if (!litPath()) {
            bits = map_compare_->shadowBits(receivers, *maps_, ctx.currentLight(), compare_, views);
            return;
        }
        map_compare_->resize(receivers, compare_.stride);  // for raiseLevels()
        bits = lit_bits_->read(int(views_.size()), compare_.stride);
    });
    // The CPU's work on the bits (r.cpu_ms), less raiseLevels()' upload.
    auto cpu_start = std::chrono::steady_clock::now();
    auto addCpuTime = [&] {
        const auto now = std::chrono::steady_clock::now();
        r.cpu_ms += std::chrono::duration<double, std::milli>(now - cpu_start).count();
        cpu_start = now;
    };
    if (level == 0) {
        shadowed_ = bits.anyShadowed(corners);
        const double per_pixel = shadowed_ > 0 ? kErrorCalibration * bits.scale / shadowed_ : 0.0;
        if (rss_estimate_) budget.emplace(target_error_, bits.pixels, per_pixel);
    }
    // The sum needs each pair's count alone; the per-pixel budget, where each cell disagrees.
    const Disagreements found =
        bits.disagreements(pairs, rss_estimate_ || tiles_->count() > 1, cell_tiles_, tile_of_);
    std::vector<double> errors;
    for (size_t i = 0; i < cells.size(); ++i) {
        r.comparisons += int(pairs[i].size());
        errors.push_back(kDisagreementError *
                         std::ldexp(1.0, -(tree.linear() ? 1 : 2) * cells[i].depth));
    }
    addCpuTime();
    // The diagnostic: the pixels where some cell disagrees.
    if (!light_centre_) map_compare_->raiseLevels(found.anywhere, level);
    cpu_start = std::chrono::steady_clock::now();
    std::vector<QuadtreeCell> next;
    if (!rss_estimate_) {  // the sum: each cell's worse diagonal, as the queries count it
        std::vector<CompareResult> counts;
        for (size_t n : found.pairs) counts.push_back({double(n) * bits.scale, 0.0});
        const std::vector<double> cell_errors = cellErrors(tree, cells, counts, shadowed_);
        next = splitInTiles(
            tree, cells, sum_budget.choose(cell_errors), found.where,
            [&](size_t i) { sum_budget.refused(cell_errors[i]); }, r.budget_hit);
    } else {
        next = splitInTiles(
            tree, cells, budget->choose(errors, found.where), found.where,
            [&](size_t i) { budget->refused(i); }, r.budget_hit);
    }
    addCpuTime();
    return next;
}

}  // namespace penumbra::techniques::adaptive
