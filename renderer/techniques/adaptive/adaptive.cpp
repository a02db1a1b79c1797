// `adaptive`: Schwärzler 2009, adaptive light-source sampling. Shadow maps at the light's
// corners, refined by a quadtree wherever two maps disagree on too many camera pixels.
#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

#include "renderer/core/error.h"
#include "renderer/passes/bindings.h"
#include "renderer/techniques/adaptive/error_budget.h"
#include "renderer/techniques/adaptive/light_quadtree.h"
#include "renderer/techniques/adaptive/map_compare.h"
#include "renderer/techniques/light_sampling.h"
#include "renderer/techniques/registry_entries.h"

namespace penumbra::techniques {
namespace {

enum class Metric { Error, Global, Tile };
enum class Compare { Auto, Depth, ShadowTest };
enum class GammaMode { Absolute, Relative };
enum class Reprojection { Camera, LightCentre };
enum class MetricArea { Map, Screen };
enum class Subdivision { Auto, Quad, Linear };
enum class Evaluation { Array, Accumulate };
using Weighting = adaptive::LightQuadtree::Weighting;

constexpr EnumKey<Metric, 3> kMetric{"metric", {"error", "global", "tile"}};
constexpr EnumKey<Compare, 3> kCompare{"compare", {"auto", "depth", "shadow_test"}};
constexpr EnumKey<GammaMode, 2> kGammaMode{"gamma_mode", {"absolute", "relative"}};
constexpr EnumKey<Reprojection, 2> kReprojection{"reprojection", {"camera", "light_centre"}};
constexpr EnumKey<MetricArea, 2> kMetricArea{"metric_area", {"map", "screen"}};
constexpr EnumKey<Subdivision, 3> kSubdivision{"subdivision", {"auto", "quad", "linear"}};
constexpr EnumKey<Weighting, 3> kWeights{"weights", {"area", "paper", "equal"}};
constexpr EnumKey<Evaluation, 2> kEvaluation{"evaluation", {"array", "accumulate"}};

constexpr std::array kAdaptiveParams = {
    enumParam(kMetric, Metric::Error,
              "error: split the cells whose corner maps leave the largest estimated visibility "
              "error until the frame's estimate is at most target_error (independent of the "
              "image size); global: eq. 4 with epsilon over the whole frame (paper); tile: "
              "refine when any screen tile's disagreeing share reaches tile_epsilon (the local "
              "metric 5.1 asks for)"),
    floatParam("target_error", 0.02, 0.0, 1.0,
               "metric \"error\": the shadow-region error of visibility (mean |V - V_true| over "
               "shadowed pixels) that the light's subdivision may leave; a cell's estimate is "
               "1/4 x its share of the light x its disagreeing over the shadowed pixels"),
    floatParam("epsilon", 0.003, 0.0, 1.0,
               "metric \"global\": refine when disagreeing pixels / metric area >= epsilon "
               "(eq. 4)"),
    floatParam("gamma", 0.01, 0.0, 1.0,
               "two stored depths are equal when they differ by less than gamma (eq. 3 / 7)"),
    enumParam(kCompare, Compare::Auto,
              "what two maps are compared on: their stored depths (paper, with gamma) or their "
              "hard-shadow test results for the receiver; auto: shadow_test for metric "
              "\"error\" (disagreeing tests are where visibility varies), depth otherwise"),
    enumParam(kGammaMode, GammaMode::Absolute,
              "depth test: absolute |d_a - d_b| (eq. 3) or relative |1 - d_a/d_b| (eq. 7)"),
    enumParam(kReprojection, Reprojection::Camera,
              "where maps are compared: the camera view (view-dependent) or a map_size^2 view "
              "from the light's centre (view-independent, section 4.1)"),
    intParam("tile_size", 32, 4, 1024, "tile side in pixels for metric \"tile\""),
    floatParam("tile_epsilon", 0.05, 0.0, 1.0,
               "metric \"tile\": refine when disagreeing pixels / tile pixels >= this"),
    enumParam(kMetricArea, MetricArea::Map,
              "eq. 4's denominator: shadow-map texels SM_x*SM_y (paper) or camera pixels"),
    intParam("compare_stride", 2, 1, 8,
             "compare at every k-th pixel along x and y of the comparison view, counting each "
             "disagreement as k^2 pixels (1: every pixel, as the paper)"),
    intParam("max_depth", 3, 0, 8, "deepest quadtree level"),
    intParam("max_maps", 81, 4, 1024, "most shadow maps per light (refinement stops there)"),
    enumParam(kSubdivision, Subdivision::Auto,
              "quad: 2D quadtree; linear: 1D halving along the light's width; auto: linear when "
              "the light's height is below 1/1000 of its width (the scene format rejects 0)"),
    enumParam(kWeights, Weighting::Area,
              "sample weights, normalised: area (each leaf cell's area shared by its corners), "
              "paper (1/(2^d+1)^2, eq. 5/6) or equal"),
    enumParam(kEvaluation, Evaluation::Array,
              "array: all maps in one pass over a texture array (3.4.2); accumulate: each map "
              "added to the accumulation buffer right after it is rendered (3.4.1)"),
    boolParam("jitter", true,
              "move each sample to a random point of its finest-grid cell (false: the paper's "
              "regular lattice, which aliases with edges parallel to the light's)"),
    intParam("seed", 1, 0, 1 << 30, "seed of the jitter pattern"),
    intParam("pcf", 1, 1, 15, "PCF kernel width in texels in the evaluation (3.4.3)"),
    mapSizeParam(1024),
    kNormalOffsetParam,
    kDepthBiasParam,
};

// Maps rendered per draw into the scratch array before they are copied to their layers.
constexpr int kScratchLayers = 16;

class Adaptive final : public Technique {
public:
    explicit Adaptive(const Params& p)
        : error_metric_(p.getEnum(kMetric) == Metric::Error),
          target_error_(p.getFloat("target_error")),
          epsilon_(p.getFloat("epsilon")),
          screen_metric_(p.getEnum(kMetricArea) == MetricArea::Screen),
          tile_epsilon_(p.getFloat("tile_epsilon")),
          light_centre_(p.getEnum(kReprojection) == Reprojection::LightCentre),
          max_depth_(p.getInt("max_depth")),
          max_maps_(p.getInt("max_maps")),
          weighting_(p.getEnum(kWeights)),
          accumulate_path_(p.getEnum(kEvaluation) == Evaluation::Accumulate),
          subdivision_(p.getEnum(kSubdivision)),
          jitter_(p.getBool("jitter")),
          seed_(static_cast<unsigned>(p.getInt("seed"))),
          settings_(samplingSettings(p)) {
        compare_.gamma = static_cast<float>(p.getFloat("gamma"));
        compare_.relative = p.getEnum(kGammaMode) == GammaMode::Relative;
        const Compare compare = p.getEnum(kCompare);
        compare_.tests =
            compare == Compare::ShadowTest || (compare == Compare::Auto && error_metric_);
        compare_.normal_offset = settings_.test.normal_offset;
        compare_.depth_bias = settings_.test.depth_bias;
        if (p.getEnum(kMetric) == Metric::Tile) compare_.tile_size = p.getInt("tile_size");
        compare_.stride = p.getInt("compare_stride");
        settings_.test.pcf = p.getInt("pcf");
        if (accumulate_path_ && weighting_ == Weighting::Area)
            throw RuntimeError(
                "adaptive: evaluation \"accumulate\" adds each map when it is rendered, before "
                "its area weight is known: use weights \"paper\" or \"equal\"");
    }

    void prepare(const gl::ContextInfo& gl, const passes::GpuScene&) override {
        max_maps_ =
            std::min({max_maps_, std::max(gl.max_array_layers, 2), passes::kMaxSampleLookups});
        maps_ = std::make_unique<passes::ShadowMapBatch>(settings_.map_size, max_maps_,
                                                         gl.has_vertex_layer);
        scratch_ = std::make_unique<passes::ShadowMapBatch>(
            settings_.map_size, std::min(kScratchLayers, max_maps_), gl.has_vertex_layer);
        accumulate_ = std::make_unique<passes::ShadowAccumulate>();
        map_compare_ = std::make_unique<adaptive::MapCompare>();
        if (light_centre_)
            light_view_ = std::make_unique<passes::GBuffer>(settings_.map_size, settings_.map_size);
    }

    std::vector<DiagnosticChannel> diagnostics() const override {
        return {{"depth", DiagnosticChannel::Combine::Max}};
    }

    void render(frame::FrameContext& ctx) override {
        const scene::RectLight& light = ctx.currentLight();
        const bool linear =
            subdivision_ == Subdivision::Linear ||
            (subdivision_ == Subdivision::Auto && light.size.y <= 1e-3f * light.size.x);
        adaptive::LightQuadtree tree(max_depth_, linear, jitter_, seed_);
        views_.clear();
        ctx.bindOutput();
        const float zero[4] = {0, 0, 0, 0};
        glClearBufferfv(GL_COLOR, 0, zero);
        glClearBufferfv(GL_COLOR, 1, zero);

        if (light_centre_) {
            const passes::CameraMatrices m = lightCentreView(ctx);
            ctx.pass("adaptive_light_view", [&] { light_view_->render(ctx.gpu, m); });
        }
        const passes::GBuffer& receivers = light_centre_ ? *light_view_ : ctx.gbuffer;
        const double area = screen_metric_
                                ? double(receivers.width()) * double(receivers.height())
                                : double(settings_.map_size) * double(settings_.map_size);
        map_compare_->clearLevels();
        std::vector<adaptive::QuadtreeCell> cells{tree.root()};
        int comparisons = 0, level = 0;
        bool budget_hit = false;
        adaptive::ErrorBudget budget(target_error_);
        double shadowed = 0;  // metric "error": pixels any corner map shadows
        for (;; ++level) {
            renderNewMaps(ctx, tree, level);
            if (level >= max_depth_ || cells.empty()) break;
            // Both diagonals (or the ends) of every cell of this level, one query each.
            std::vector<adaptive::CompareResult> counts;
            int queued = 0;
            for (const auto& c : cells) queued += int(tree.comparisons(c).size());
            ctx.pass("adaptive_compare[" + std::to_string(level) + "]", [&] {
                const bool count_shadowed = error_metric_ && level == 0;
                map_compare_->begin(receivers, *maps_, light, compare_, queued + count_shadowed);
                for (const auto& c : cells)
                    for (auto [a, b] : tree.comparisons(c)) map_compare_->compare(a, b, level);
                if (count_shadowed)
                    map_compare_->countShadowed(tree.linear() ? std::array{0, 1, 0, 1}
                                                              : std::array{0, 1, 2, 3});
                counts = map_compare_->end();
                if (count_shadowed) {
                    shadowed = counts.back().pixels;
                    counts.pop_back();
                }
            });
            comparisons += static_cast<int>(counts.size());
            cells = error_metric_ ? splitByError(tree, cells, counts, shadowed, budget, budget_hit)
                                  : splitCells(tree, cells, counts, area, budget_hit);
        }
        // The diagnostic: where comparisons in the camera view disagreed, and how deep.
        if (!light_centre_ && comparisons > 0) {
            ctx.bindOutput();
            GLint output = 0;
            glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &output);
            map_compare_->writeLevels(GLuint(output));
        }

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
            // All maps of the light in one pass over the texture array (3.4.2).
            const auto weights = tree.weights(weighting_);
            for (size_t i = 0; i < views_.size(); ++i) {
                views_[i].origin.w = weights[i];
                views_[i].depth.y = weights[i];
            }
            views_buffer_.upload(views_);
            ctx.pass("adaptive_eval", [&] {
                ctx.bindOutput();
                addToVisibility(ctx, *maps_, 0, n);
            });
        }

        int depth_reached = 0;
        for (const auto& s : tree.samples()) depth_reached = std::max(depth_reached, s.depth);
        auto& st = ctx.stats;
        st["maps_rendered"] = st.value("maps_rendered", 0) + n;
        st["comparisons"] = st.value("comparisons", 0) + comparisons;
        st["queries"] = st.value("queries", 0) + comparisons;
        st["depth_reached"] = std::max(st.value("depth_reached", 0), depth_reached);
        st["map_budget_hit"] = st.value("map_budget_hit", false) || budget_hit;
        if (error_metric_)
            st["estimated_error"] = std::max(st.value("estimated_error", 0.0), budget.estimate());
    }

private:
    // Whether splitting CELL keeps the light's maps within max_maps.
    bool fitsMapBudget(const adaptive::LightQuadtree& tree,
                       const adaptive::QuadtreeCell& cell) const {
        return int(tree.samples().size()) + tree.newSamples(cell) <= max_maps_;
    }

    // Metric "error": splits the CELLS whose estimated error (from COUNTS, in comparisons()
    // order, over SHADOWED pixels) BUDGET chooses, within the map budget; returns the children.
    std::vector<adaptive::QuadtreeCell> splitByError(
        adaptive::LightQuadtree& tree, const std::vector<adaptive::QuadtreeCell>& cells,
        const std::vector<adaptive::CompareResult>& counts, double shadowed,
        adaptive::ErrorBudget& budget, bool& budget_hit) const {
        std::vector<double> errors;
        for (size_t i = 0, q = 0; i < cells.size(); ++i) {
            double disagreeing = 0;  // the worse diagonal
            for (size_t k = 0; k < tree.comparisons(cells[i]).size(); ++k, ++q)
                disagreeing = std::max(disagreeing, counts[q].pixels);
            const double share = std::ldexp(1.0, -(tree.linear() ? 1 : 2) * cells[i].depth);
            errors.push_back(adaptive::cellError(share, disagreeing, shadowed));
        }
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

    // Splits the CELLS whose comparisons (COUNTS, in comparisons() order) fail the metric, most
    // disagreeing first so that the map budget goes where it matters; returns their children.
    std::vector<adaptive::QuadtreeCell> splitCells(
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
    passes::CameraMatrices lightCentreView(const frame::FrameContext& ctx) const {
        const scene::RectLight& light = ctx.currentLight();
        const passes::SampleView v = passes::makeSampleView(
            light, light.position, ctx.gpu.casterBounds(), 1.0f, settings_.map_size);
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
    void renderNewMaps(frame::FrameContext& ctx, const adaptive::LightQuadtree& tree, int level) {
        const scene::RectLight& light = ctx.currentLight();
        const auto corners = light.corners();
        const int first = static_cast<int>(views_.size());
        for (size_t i = views_.size(); i < tree.samples().size(); ++i) {
            const glm::vec2 uv = tree.samples()[i].uv;
            glm::vec3 p =
                corners[0] + (corners[1] - corners[0]) * uv.x + (corners[3] - corners[0]) * uv.y;
            views_.push_back(
                passes::makeSampleView(light, p, ctx.gpu.casterBounds(), 1.0f, settings_.map_size));
        }
        const int n = static_cast<int>(views_.size());
        if (first == n) return;
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
        ctx.pass("adaptive_maps[" + std::to_string(level) + "]", [&] {
            for (int base = first; base < n; base += scratch_->layers()) {
                const int count = std::min(scratch_->layers(), n - base);
                scratch_->render(ctx.gpu, base, count);
                copyToMaps(base, count);
            }
        });
    }

    // Copies scratch layers 0..COUNT-1 to maps_ layers BASE.. (layer = view index there).
    void copyToMaps(int base, int count) {
        glCopyImageSubData(scratch_->depth().id(), GL_TEXTURE_2D_ARRAY, 0, 0, 0, 0,
                           maps_->depth().id(), GL_TEXTURE_2D_ARRAY, 0, 0, 0, base,
                           settings_.map_size, settings_.map_size, count);
    }

    // Adds the weighted tests of BATCH's COUNT views from VIEW_BASE to the bound visibility.
    void addToVisibility(frame::FrameContext& ctx, const passes::ShadowMapBatch& batch,
                         int view_base, int count) {
        glColorMaski(1, GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
        glEnable(GL_BLEND);
        glBlendEquation(GL_FUNC_ADD);
        glBlendFunc(GL_ONE, GL_ONE);
        accumulate_->render(ctx.gbuffer, batch, view_base, count, ctx.currentLight(),
                            settings_.test, ctx.gpu.casterFlags());
        glDisable(GL_BLEND);
        glColorMaski(1, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    }

    // The unnormalised weight of a sample created at DEPTH (eq. 5/6), or 1.
    float sampleWeight(const adaptive::LightQuadtree& tree, int depth) const {
        if (weighting_ == adaptive::LightQuadtree::Weighting::Equal) return 1.0f;
        const float per_axis = 1.0f / (std::ldexp(1.0f, depth) + 1.0f);
        return tree.linear() ? per_axis : per_axis * per_axis;
    }

    bool error_metric_;
    double target_error_;
    double epsilon_;
    bool screen_metric_;
    double tile_epsilon_;
    bool light_centre_;
    int max_depth_;
    int max_maps_;
    adaptive::LightQuadtree::Weighting weighting_;
    bool accumulate_path_;
    Subdivision subdivision_;
    bool jitter_;
    unsigned seed_;
    SamplingSettings settings_;
    adaptive::CompareSettings compare_;
    std::unique_ptr<passes::ShadowMapBatch> maps_, scratch_;
    std::unique_ptr<passes::ShadowAccumulate> accumulate_;
    std::unique_ptr<adaptive::MapCompare> map_compare_;
    std::unique_ptr<passes::GBuffer> light_view_;  // receivers seen from the light's centre
    passes::SampleViewBuffer views_buffer_;
    std::vector<passes::SampleView> views_;
};

}  // namespace

const TechniqueInfo kAdaptiveTechnique = {
    "adaptive",
    "adaptive light sampling (Schwarzler 2009): corner maps refined by a quadtree where maps "
    "disagree in the camera view",
    kAdaptiveParams,
    [](const Params& p) -> std::unique_ptr<Technique> { return std::make_unique<Adaptive>(p); }};

}  // namespace penumbra::techniques
