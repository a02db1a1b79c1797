// `adaptive`: Schwärzler 2009, adaptive light-source sampling. Shadow maps at the light's
// corners, refined by a quadtree wherever two maps disagree on too many camera pixels.
#include "renderer/techniques/adaptive/adaptive.h"

#include <algorithm>
#include <cstdint>
#include <optional>
#include <string>

#include "renderer/core/error.h"
#include "renderer/core/memory_limit.h"
#include "renderer/passes/bindings.h"
#include "renderer/techniques/registry_entries.h"

namespace penumbra::techniques {
namespace adaptive {

Adaptive::Adaptive(const Params& p)
    : error_metric_(p.getEnum(kMetric) == Metric::Error),
      target_error_(p.get(kTargetError)),
      epsilon_(p.get(kEpsilon)),
      screen_metric_(p.getEnum(kMetricArea) == MetricArea::Screen),
      tile_epsilon_(p.get(kTileEpsilon)),
      light_centre_(p.getEnum(kReprojection) == Reprojection::LightCentre),
      max_depth_(p.get(kMaxDepth)),
      max_maps_(p.get(kMaxMaps)),
      weighting_(p.getEnum(kWeights)),
      accumulate_path_(p.getEnum(kEvaluation) == Evaluation::Accumulate),
      rss_estimate_(p.getEnum(kEstimate) == Estimate::Rss),
      bits_storage_(p.getEnum(kStorage) == Storage::Auto),
      skip_lit_(p.get(kSkipLit)),
      subdivision_(p.getEnum(kSubdivision)),
      jitter_(p.get(kJitter)),
      seed_(static_cast<unsigned>(p.get(kSeed))),
      max_texel_(p.get(kMaxTexel)),
      settings_(samplingSettings(p)),
      map_size_(settings_.map_size) {
    compare_.gamma = static_cast<float>(p.get(kGamma));
    compare_.relative = p.getEnum(kGammaMode) == GammaMode::Relative;
    const Compare compare = p.getEnum(kCompare);
    compare_.tests = compare == Compare::ShadowTest || (compare == Compare::Auto && error_metric_);
    compare_.normal_offset = settings_.test.normal_offset;
    compare_.depth_bias = settings_.test.depth_bias;
    if (p.getEnum(kMetric) == Metric::Tile) compare_.tile_size = p.get(kTileSize);
    compare_.stride = p.get(kCompareStride);
    settings_.test.pcf = p.get(kPcf);
    refine_tile_ = p.get(kRefineTile);
    if (accumulate_path_ && weighting_ == Weighting::Area)
        throw RuntimeError(
            "adaptive: evaluation \"accumulate\" adds each map when it is rendered, before "
            "its area weight is known: use weights \"paper\" or \"equal\"");
}

void Adaptive::prepare(const gl::ContextInfo& gl, const passes::GpuScene&) {
    max_maps_ = std::min({mapLayers(max_maps_, settings_.map_size),
                          std::max(gl.max_array_layers, 2), passes::kMaxSampleLookups});
    vertex_layer_ = gl.has_vertex_layer;
    maps_.reset();         // reserveMaps() sizes it by what refinement reaches
    if (accumulate_path_)  // one map at a time, accumulated from layer 0
        scratch_ =
            std::make_unique<passes::ShadowMapBatch>(settings_.map_size, 1, gl.has_vertex_layer);
    if (litPath()) {  // a batch at a time, kept as shadow bits
        scratch_ = std::make_unique<passes::ShadowMapBatch>(
            settings_.map_size, std::min(kTestBatch, std::max(gl.max_array_layers, 1)),
            gl.has_vertex_layer);
        lit_bits_ = std::make_unique<adaptive::LitBits>();
        if (skip_lit_) {
            region_ = std::make_unique<passes::DistancePyramid>(regionSize(settings_.map_size),
                                                                "adaptive lit region");
            region_pass_ = std::make_unique<passes::LightDepthPass>(
                "adaptive lit region depth", passes::LightDepthPass::Output::Distance);
        }
    }
    accumulate_ = std::make_unique<passes::ShadowAccumulate>();
    map_compare_ = std::make_unique<adaptive::MapCompare>();
    if (light_centre_)
        light_view_ = std::make_unique<passes::GBuffer>(settings_.map_size, settings_.map_size);
}

void Adaptive::render(frame::FrameContext& ctx) {
    const scene::RectLight& light = ctx.currentLight();
    const bool linear = subdivision_ == Subdivision::Linear ||
                        (subdivision_ == Subdivision::Auto && light.size.y <= 1e-3f * light.size.x);
    adaptive::LightQuadtree tree(max_depth_, linear, jitter_, seed_);
    views_.clear();
    compare_.caster_flags = ctx.gpu.casterFlags().id();
    chooseMapSize(ctx);
    ctx.bindOutput();
    const float zero[4] = {0, 0, 0, 0};
    glClearBufferfv(GL_COLOR, 0, zero);
    glClearBufferfv(GL_COLOR, 1, zero);
    if (litPath()) {
        lit_bits_->begin(ctx.gbuffer, max_maps_);
        renderLitRegion(ctx);
    }

    if (light_centre_) {
        const passes::CameraMatrices m = lightCentreView(ctx);
        ctx.pass("adaptive_light_view", [&] { light_view_->render(ctx.gpu, m); });
    }
    const passes::GBuffer& receivers = light_centre_ ? *light_view_ : ctx.gbuffer;
    tiles_.emplace(litPath() ? refine_tile_ : 0, receivers.width(), receivers.height());
    tile_of_ = tiles_->tilesAtStride(compare_.stride);
    cell_tiles_ = {tiles_->all()};
    horizon_tiles_ = TileMask(size_t(tiles_->count()), 0);
    if (litPath() && tiles_->count() > 1)
        ctx.pass("adaptive_horizon_tiles", [&] {
            horizon_tiles_ =
                lit_bits_->horizonTiles(ctx.gbuffer, light, ctx.gpu.casterFlags(), *tiles_);
        });
    view_tiles_.clear();
    tiled_leaves_.clear();
    const double area = screen_metric_ ? double(receivers.width()) * double(receivers.height())
                                       : double(settings_.map_size) * double(settings_.map_size);
    const Refinement r = refine(ctx, tree, receivers, area);
    // The diagnostic: where comparisons in the camera view disagreed, and how deep.
    if (!light_centre_ && r.comparisons > 0) map_compare_->writeLevels(ctx.bindOutput());

    evaluate(ctx, tree);
    addStatistics(ctx, tree, r);
}

// Renders the corner maps and refines the light's quadtree level by level where maps
// disagree (RECEIVERS: the pixels compared; AREA: the metric's pixel count).
Refinement Adaptive::refine(frame::FrameContext& ctx, adaptive::LightQuadtree& tree,
                            const passes::GBuffer& receivers, double area) {
    const scene::RectLight& light = ctx.currentLight();
    map_compare_->clearLevels();
    std::vector<adaptive::QuadtreeCell> cells{tree.root()};
    Refinement r;
    int level = 0;
    adaptive::ErrorBudget budget(target_error_);
    double shadowed = 0;  // metric "error": pixels any corner map shadows
    std::optional<adaptive::PixelErrorBudget> pixel_budget;  // the bits path's
    for (;; ++level) {
        renderNewMaps(ctx, tree, level);
        if (level >= max_depth_ || cells.empty()) {
            for (size_t i = 0; i < cells.size() && bitsPath(); ++i)  // leaves where they live
                tiled_leaves_.push_back({cells[i], cell_tiles_[i]});
            break;
        }
        if (bitsPath()) {
            cells = refineByBits(ctx, tree, cells, receivers, level, budget, pixel_budget, r);
            continue;
        }
        std::vector<adaptive::CompareResult> counts;
        ctx.pass("adaptive_compare[" + std::to_string(level) + "]", [&] {
            const bool count_shadowed = error_metric_ && level == 0;
            counts = compareByQueries(tree, cells, receivers, light, level, count_shadowed);
            if (count_shadowed) {
                shadowed = counts.back().pixels;
                counts.pop_back();
            }
        });
        r.comparisons += static_cast<int>(counts.size());
        r.queries += static_cast<int>(counts.size());
        cells = error_metric_ ? splitByError(tree, cells, counts, shadowed, budget, r.budget_hit)
                              : splitCells(tree, cells, counts, area, r.budget_hit);
    }
    if (error_metric_)
        r.estimated_error = pixel_budget ? pixel_budget->estimate() : budget.estimate();
    return r;
}

// Both diagonals (or the ends) of every cell of this level, one occlusion query each, and with
// COUNT_SHADOWED the pixels any root corner shadows last.
std::vector<adaptive::CompareResult> Adaptive::compareByQueries(
    const adaptive::LightQuadtree& tree, const std::vector<adaptive::QuadtreeCell>& cells,
    const passes::GBuffer& receivers, const scene::RectLight& light, int level,
    bool count_shadowed) {
    int queued = 0;
    for (const auto& c : cells) queued += int(tree.comparisons(c).size());
    map_compare_->begin(receivers, *maps_, light, compare_, queued + count_shadowed);
    for (const auto& c : cells)
        for (auto [a, b] : tree.comparisons(c)) map_compare_->compare(a, b, level);
    if (count_shadowed)
        map_compare_->countShadowed(tree.linear() ? std::array{0, 1, 0, 1}
                                                  : std::array{0, 1, 2, 3});
    return map_compare_->end();
}

void Adaptive::renderLitRegion(frame::FrameContext& ctx) {
    if (!region_) return;
    const scene::RectLight& light = ctx.currentLight();
    LitRegion region;
    // The casters' own window: lit_region.frag's search scales each axis by its texel, so the
    // light's aspect is not needed (stretched to a 1500:1 strip light's, the casters fell
    // between the texels and nothing was marked: no shadow at all).
    region.window = passes::windowOf(light, ctx.gpu.casterBoxes());
    if (region.window.empty()) return;  // no caster: the tests find none either
    // The tests' normal offset scales with view 0's texel size; the centre's is nearly the same.
    const float texel =
        passes::makeSampleView(light, light.position, ctx.gpu.casterBoxes(), 1.0f, map_size_)
            .params.y;
    ctx.pass("adaptive_lit_region", [&] {
        region_->render(*region_pass_, ctx.gpu, light, region.window.viewProj(light));
        region_->build();
        region.pyramid = region_->texture().id();
        region.size = region_->size();
        region.levels = region_->levels();
        lit_bits_->markLitRegion(ctx.gbuffer, light, compare_, texel, region);
    });
}

void Adaptive::chooseMapSize(const frame::FrameContext& ctx) {
    const scene::RectLight& light = ctx.currentLight();
    const int max_size = settings_.map_size;
    const passes::SampleView centre =
        passes::makeSampleView(light, light.position, ctx.gpu.casterBoxes(), 1.0f, max_size);
    // params.y is the window's widest side and its 2-texel margin over the side.
    const double extent = double(centre.params.y) * max_size * max_size / (max_size + 2.0);
    map_size_ = mapSideFor(max_size, max_texel_, extent);
    if (scratch_ && scratch_->mapSize() != map_size_)
        scratch_ =
            std::make_unique<passes::ShadowMapBatch>(map_size_, scratch_->layers(), vertex_layer_);
    if (maps_ && maps_->mapSize() != map_size_) maps_.reset();  // reserveMaps() makes it again
}

// Adds the light's maps, weighted, into its visibility.
void Adaptive::evaluate(frame::FrameContext& ctx, const adaptive::LightQuadtree& tree) {
    const scene::RectLight& light = ctx.currentLight();
    const int n = static_cast<int>(views_.size());
    if (accumulate_path_) {
        // The buffer holds sum_k w_k lit_k with unnormalised weights: scale by 1 / sum w.
        double sum = 0;
        for (const auto& s : tree.samples()) sum += sampleWeight(tree, s.depth);
        ctx.pass("adaptive_normalise", [&] {
            ctx.bindOutput();
            glColorMaski(1, GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
            glEnable(GL_BLEND);
            glBlendEquation(GL_FUNC_ADD);
            const float scale = static_cast<float>(1.0 / sum);
            glBlendColor(scale, scale, scale, scale);
            glBlendFunc(GL_ZERO, GL_CONSTANT_COLOR);  // dst * scale; the source adds 0
            accumulate_->render(ctx.gbuffer, *maps_, 0, 0, light, settings_.test,
                                ctx.gpu.casterFlags());
            glBlendFunc(GL_ONE, GL_ONE);
            glDisable(GL_BLEND);
            glColorMaski(1, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        });
    } else {
        // All maps of the light in one pass over the texture array (3.4.2), or over their bits.
        const auto weights = tree.weights(weighting_);
        for (size_t i = 0; i < views_.size(); ++i) {
            views_[i].origin.w = weights[i];
            views_[i].depth.y = weights[i];
        }
        views_buffer_.upload(views_);
        ctx.pass("adaptive_eval", [&] {
            const GLuint output = ctx.bindOutput();
            if (!litPath()) return addToVisibility(ctx, *maps_, 0, n);
            glColorMaski(1, GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
            glEnable(GL_BLEND);
            glBlendEquation(GL_FUNC_ADD);
            glBlendFunc(GL_ONE, GL_ONE);
            const adaptive::TileWeights tile_weights =
                adaptive::tileWeights(tree, weighting_, tiled_leaves_, tiles_->count());
            lit_bits_->evaluate(output, ctx.gbuffer, n, light, ctx.gpu.casterFlags(), *tiles_,
                                tile_weights);
            glDisable(GL_BLEND);
            glColorMaski(1, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        });
    }
}

// The light's statistics, summed (or maxed) over lights.
void Adaptive::addStatistics(frame::FrameContext& ctx, const adaptive::LightQuadtree& tree,
                             const Refinement& r) const {
    const int n = static_cast<int>(views_.size());
    int depth_reached = 0;
    for (const auto& s : tree.samples()) depth_reached = std::max(depth_reached, s.depth);
    auto& st = ctx.stats;
    st["maps_rendered"] = st.value("maps_rendered", 0) + n;
    st["map_size"] = std::max(st.value("map_size", 0), map_size_);
    st["comparisons"] = st.value("comparisons", 0) + r.comparisons;
    st["queries"] = st.value("queries", 0) + r.queries;
    st["depth_reached"] = std::max(st.value("depth_reached", 0), depth_reached);
    st["map_budget_hit"] = st.value("map_budget_hit", false) || r.budget_hit;
    // The most maps alive at once: a batch on the lit path, else the array's layers.
    const int held = litPath() ? scratch_->layers() : maps_ ? maps_->layers() : 0;
    st["maps_held"] = std::max(st.value("maps_held", 0), held);
    if (const auto tested = lit_bits_ ? lit_bits_->markedPixels() : std::nullopt)  // skip_lit
        st["tested_pixels"] = st.value("tested_pixels", 0.0) + *tested;
    if (litPath() && n > 0) {  // the share of (view, screen tile) pairs tested, the most of a light
        double tested = 0;
        for (const auto& tiles : view_tiles_)
            tested += double(std::count(tiles.begin(), tiles.end(), 1));
        const double share = tested / (double(n) * double(tiles_->count()));
        st["tested_tile_share"] = std::max(st.value("tested_tile_share", 0.0), share);
    }
    if (error_metric_)
        st["estimated_error"] = std::max(st.value("estimated_error", 0.0), r.estimated_error);
    // CPU work between passes, which a GPU's timer queries leave out or put in a pass's time.
    if (r.cpu_ms > 0) st["refine_cpu_ms"] = st.value("refine_cpu_ms", 0.0) + r.cpu_ms;
}

// Adds the weighted tests of BATCH's COUNT views from VIEW_BASE to the bound visibility.
void Adaptive::addToVisibility(frame::FrameContext& ctx, const passes::ShadowMapBatch& batch,
                               int view_base, int count) {
    glColorMaski(1, GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glEnable(GL_BLEND);
    glBlendEquation(GL_FUNC_ADD);
    glBlendFunc(GL_ONE, GL_ONE);
    accumulate_->render(ctx.gbuffer, batch, view_base, count, ctx.currentLight(), settings_.test,
                        ctx.gpu.casterFlags());
    glDisable(GL_BLEND);
    glColorMaski(1, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
}

// The unnormalised weight of a sample created at DEPTH (eq. 5/6), or 1.
float Adaptive::sampleWeight(const adaptive::LightQuadtree& tree, int depth) const {
    if (weighting_ == adaptive::LightQuadtree::Weighting::Equal) return 1.0f;
    const float per_axis = 1.0f / (std::ldexp(1.0f, depth) + 1.0f);
    return tree.linear() ? per_axis : per_axis * per_axis;
}

}  // namespace adaptive

const TechniqueInfo kAdaptiveTechnique = {
    "adaptive",
    "adaptive light sampling (Schwarzler 2009): corner maps refined by a quadtree where maps "
    "disagree in the camera view",
    adaptive::kAdaptiveParams,
    [](const Params& p) -> std::unique_ptr<Technique> {
        return std::make_unique<adaptive::Adaptive>(p);
    },
    nullptr,
    // The maps, the accumulation path's scratch map and the light-view G-buffer (48 bytes a
    // texel).
    [](const Params& p, std::uint64_t pixels) {
        const int maps = adaptive::mapLayers(p.get(adaptive::kMaxMaps), p.get(kMapSize));
        const auto m = static_cast<std::uint64_t>(p.get(kMapSize));
        MemoryTerms out = {shadowMapArrayTerm(p, maps)};
        // The lit path's batch and bits (the array's term stays: a bound on both paths), with
        // the test passes' stencil and the evaluation's depth (two words a pixel bound them).
        out.push_back({"image.width", "the per-pixel shadow bits of the maps",
                       saturatingProduct({pixels, std::uint64_t(maps + 31) / 32 + 2, 4})});
        if (p.getEnum(adaptive::kEvaluation) == adaptive::Evaluation::Accumulate) {
            out.push_back(shadowMapArrayTerm(p, 1));
            out.back().what = "the scratch map";
        }
        out.push_back(
            {"technique.map_size", "the light-view G-buffer", saturatingProduct({m, m, 48})});
        // The lit region's distance pyramid (RG32F, 4/3 for its mips) and its 32-bit depth.
        const auto r = static_cast<std::uint64_t>(adaptive::regionSize(p.get(kMapSize)));
        if (p.get(adaptive::kSkipLit))
            out.push_back({"technique.map_size", "the lit region's pyramid",
                           saturatingProduct({r, r, 8 * 4 / 3 + 4})});
        return out;
    }};

}  // namespace penumbra::techniques
