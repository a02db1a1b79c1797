// The `adaptive` technique's class, shared by its files: adaptive.cpp (parameters, resources,
// the order of passes, evaluation and statistics) and quadtree_refinement.cpp (rendering the
// light-sample maps and choosing the quadtree cells to split).
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "renderer/passes/distance_pyramid.h"
#include "renderer/passes/gbuffer.h"
#include "renderer/passes/light_depth.h"
#include "renderer/passes/shadow_maps.h"
#include "renderer/techniques/adaptive/error_budget.h"
#include "renderer/techniques/adaptive/light_quadtree.h"
#include "renderer/techniques/adaptive/lit_bits.h"
#include "renderer/techniques/adaptive/map_compare.h"
#include "renderer/techniques/adaptive/map_size.h"
#include "renderer/techniques/adaptive/pixel_error_budget.h"
#include "renderer/techniques/adaptive/screen_tiles.h"
#include "renderer/techniques/light_sampling.h"
#include "renderer/techniques/param_keys.h"
#include "renderer/techniques/technique.h"

namespace penumbra::techniques::adaptive {

enum class Metric { Error, Global, Tile };
enum class Compare { Auto, Depth, ShadowTest };
enum class GammaMode { Absolute, Relative };
enum class Reprojection { Camera, LightCentre };
enum class MetricArea { Map, Screen };
enum class Subdivision { Auto, Quad, Linear };
enum class Evaluation { Array, Accumulate };
enum class Estimate { Sum, Rss };
enum class Storage { Auto, Array };
using Weighting = LightQuadtree::Weighting;

inline constexpr EnumKey<Metric, 3> kMetric{"metric", {"error", "global", "tile"}};
inline constexpr EnumKey<Compare, 3> kCompare{"compare", {"auto", "depth", "shadow_test"}};
inline constexpr EnumKey<GammaMode, 2> kGammaMode{"gamma_mode", {"absolute", "relative"}};
inline constexpr EnumKey<Reprojection, 2> kReprojection{"reprojection", {"camera", "light_centre"}};
inline constexpr EnumKey<MetricArea, 2> kMetricArea{"metric_area", {"map", "screen"}};
inline constexpr EnumKey<Subdivision, 3> kSubdivision{"subdivision", {"auto", "quad", "linear"}};
inline constexpr EnumKey<Weighting, 3> kWeights{"weights", {"area", "paper", "equal"}};
inline constexpr EnumKey<Evaluation, 2> kEvaluation{"evaluation", {"array", "accumulate"}};
inline constexpr EnumKey<Estimate, 2> kEstimate{"estimate", {"sum", "rss"}};
inline constexpr EnumKey<Storage, 2> kStorage{"storage", {"auto", "array"}};

inline constexpr FloatKey kTargetError{"target_error"};
inline constexpr FloatKey kEpsilon{"epsilon"};
inline constexpr FloatKey kGamma{"gamma"};
inline constexpr IntKey kTileSize{"tile_size"};
inline constexpr FloatKey kTileEpsilon{"tile_epsilon"};
inline constexpr IntKey kCompareStride{"compare_stride"};
inline constexpr IntKey kMaxDepth{"max_depth"};
inline constexpr IntKey kMaxMaps{"max_maps"};
inline constexpr BoolKey kSkipLit{"skip_lit"};
inline constexpr FloatKey kMaxTexel{"max_texel"};
inline constexpr IntKey kRefineTile{"refine_tile"};

inline constexpr std::array kAdaptiveParams = {
    enumParam(kMetric, Metric::Error,
              "error: split the cells whose corner maps leave the largest estimated visibility "
              "error until the frame's estimate is at most target_error (independent of the "
              "image size); global: eq. 4 with epsilon over the whole frame (paper); tile: "
              "refine when any screen tile's disagreeing share reaches tile_epsilon (the local "
              "metric 5.1 asks for)"),
    floatParam(kTargetError, 0.02, 0.0, 1.0,
               "metric \"error\": the shadow-region error of visibility (mean |V - V_true| over "
               "shadowed pixels) that the light's subdivision may leave: a cell whose corners "
               "disagree at a pixel leaves 1/4 x its share of the light there"),
    enumParam(kEstimate, Estimate::Sum,
              "metric \"error\": how the cells' errors at one pixel combine: sum (an upper "
              "bound, 1.1-9x the error measured) or rss (root sum of squares calibrated on five "
              "conformance scenes: 0.5-1.05x the error on the corpus, cheaper but under the "
              "estimate where edges parallel to the light's make cells err alike)"),
    floatParam(kEpsilon, 0.003, 0.0, 1.0,
               "metric \"global\": refine when disagreeing pixels / metric area >= epsilon "
               "(eq. 4)"),
    floatParam(kGamma, 0.01, 0.0, 1.0,
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
    intParam(kTileSize, 32, 4, 1024, "tile side in pixels for metric \"tile\""),
    floatParam(kTileEpsilon, 0.05, 0.0, 1.0,
               "metric \"tile\": refine when disagreeing pixels / tile pixels >= this"),
    enumParam(kMetricArea, MetricArea::Map,
              "eq. 4's denominator: shadow-map texels SM_x*SM_y (paper) or camera pixels"),
    intParam(kCompareStride, 1, 1, 8,
             "compare at every k-th pixel along x and y of the comparison view, counting each "
             "disagreement as k^2 pixels (1: every pixel, as the paper; more can miss a shadow "
             "narrower than k pixels)"),
    intParam(kMaxDepth, 4, 0, 8, "deepest quadtree level"),
    intParam(kMaxMaps, 289, 4, 1024,
             "most shadow maps per light (refinement stops there; 289: the full depth-4 grid); "
             "lowered to the maps that fit 2 GiB (128 of 2048^2)"),
    enumParam(kSubdivision, Subdivision::Auto,
              "quad: 2D quadtree; linear: 1D halving along the light's width; auto: linear when "
              "the light's height is below 1/1000 of its width (the scene format rejects 0)"),
    enumParam(kWeights, Weighting::Area,
              "sample weights, normalised: area (each leaf cell's area shared by its corners), "
              "paper (1/(2^d+1)^2, eq. 5/6) or equal"),
    enumParam(kEvaluation, Evaluation::Array,
              "array: all maps in one pass over a texture array (3.4.2); accumulate: each map "
              "added to the accumulation buffer right after it is rendered (3.4.1)"),
    enumParam(kStorage, Storage::Auto,
              "auto: with metric \"error\" (hard-test comparisons), reprojection \"camera\", "
              "evaluation \"array\" and pcf 1 (the defaults), maps are rendered and tested 32 at "
              "a time and kept as one bit per pixel, which the comparisons and the evaluation "
              "read (the same image as the array); otherwise, and with array: every map is kept "
              "in a texture array until the evaluation"),
    boolParam(kSkipLit, true,
              "the default storage: a pixel where no caster lies between it and any point of the "
              "light (a min/max pyramid of the casters seen from the light's centre, searched "
              "over the pyramid from the pixel to the light) is not tested against the maps: "
              "only pixels a caster may shadow pay for every map (false: every pixel tested)"),
    intParam(kRefineTile, 0, 0, 4096,
             "the default storage: a split cell's new maps are tested, and its children "
             "weighted, only in the screen tiles (this side in pixels) where its corners "
             "disagreed, their neighbours and the tiles where a caster's tangent plane cuts "
             "the light; elsewhere the cell stays a leaf (0: the whole image, as the paper)"),
    boolParam(kJitter, true,
              "move each sample to a random point of its finest-grid cell within the light (false: "
              "the paper's regular lattice, which aliases with edges parallel to the light's)"),
    intParam(kSeed, 1, 0, 1 << 30, "seed of the jitter pattern"),
    intParam(kPcf, 1, 1, 15, "PCF kernel width in texels in the evaluation (3.4.3)"),
    mapSizeParam(1024),
    floatParam(kMaxTexel, 0.002, 0.0, 1.0,
               "map_size is the largest map, and each light's maps are the smallest multiple "
               "of 128 from 256 whose texel is at most this wide per unit distance from the light "
               "(the casters' window from the light's centre over the side): narrow windows get "
               "coarser maps, which cost less (1.5-3x faster on two conformance scenes at the "
               "same error, see the README); 0: every map at map_size"),
    kNormalOffsetParam,
    kDepthBiasParam,
};

// Maps rendered per layered draw.
inline constexpr int kScratchLayers = 16;
// Maps rendered and tested per batch where the maps are kept as shadow bits (LitBits).
inline constexpr int kTestBatch = 32;
static_assert(kTestBatch == 32, "the storage parameter's text says 32 maps a batch");

// The most bytes of the array of maps (it grows to max_maps): at larger map sizes max_maps is
// lowered to what fits (128 maps of 2048^2), never below the 4 corners.
inline constexpr std::uint64_t kMaxArrayBytes = std::uint64_t{2} << 30;
inline int mapLayers(int max_maps, int map_size) {
    const auto per_map = std::uint64_t(map_size) * std::uint64_t(map_size) * 4;
    return std::max(
        4, int(std::min<std::uint64_t>(std::uint64_t(max_maps), kMaxArrayBytes / per_map)));
}

// The lit region's pyramid side (skip_lit): the maps' size up to a power of two, at most 2048.
inline int regionSize(int map_size) {
    return int(std::bit_ceil(unsigned(std::clamp(map_size, 16, 2048))));
}

// What refining a light's quadtree found, for the statistics.
struct Refinement {
    int comparisons = 0;
    int queries = 0;  // occlusion queries (the bits path compares on the CPU)
    bool budget_hit = false;
    double estimated_error = 0.0;  // metric "error"
    double cpu_ms = 0.0;  // the bits path's comparisons and choices on the CPU (steady clock)
};

class Adaptive final : public Technique {
public:
    explicit Adaptive(const Params& p);

    void prepare(const gl::ContextInfo& gl, const passes::GpuScene&) override;

    std::vector<DiagnosticChannel> diagnostics() const override {
        return {{"depth", DiagnosticChannel::Combine::Max}};
    }

    void render(frame::FrameContext& ctx) override;

private:
    // Renders the corner maps and refines the light's quadtree level by level where maps
    // disagree (RECEIVERS: the pixels compared; AREA: the metric's pixel count).
    Refinement refine(frame::FrameContext& ctx, LightQuadtree& tree,
                      const passes::GBuffer& receivers, double area);

    // The comparison counts of CELLS' diagonals (tree.comparisons() order), one occlusion query
    // per pair, with COUNT_SHADOWED the pixels any root corner shadows last.
    std::vector<CompareResult> compareByQueries(const LightQuadtree& tree,
                                                const std::vector<QuadtreeCell>& cells,
                                                const passes::GBuffer& receivers,
                                                const scene::RectLight& light, int level,
                                                bool count_shadowed);
    // Metric "error" on shadow bits: compares CELLS from one pass over the level's corner
    // maps (each read once, however many cells share it) and splits those SUM_BUDGET chooses
    // (estimate "sum") or BUDGET (estimate "rss", made at level 0 from the pixels the root
    // corners shadow), within the map budget; returns the children.
    std::vector<QuadtreeCell> refineByBits(frame::FrameContext& ctx, LightQuadtree& tree,
                                           const std::vector<QuadtreeCell>& cells,
                                           const passes::GBuffer& receivers, int level,
                                           ErrorBudget& sum_budget,
                                           std::optional<PixelErrorBudget>& budget, Refinement& r);
    // Metric "error" on hard-test comparisons: the counts come from shadow bits.
    bool bitsPath() const { return error_metric_ && compare_.tests && compare_.tile_size == 0; }
    // The bits path in the camera view with hard tests and the array evaluation (the defaults):
    // every map is tested at every pixel once, right after it is rendered in a batch of
    // kTestBatch, and kept as a bit per pixel (LitBits); comparisons and the evaluation read
    // the bits, so no map outlives its batch.
    bool litPath() const {
        return bits_storage_ && bitsPath() && !light_centre_ && !accumulate_path_ &&
               settings_.test.pcf == 1;
    }

    // The lit path with skip_lit: the casters' distance pyramid from the light's centre, which
    // tells lit_bits.frag the pixels no caster can shadow.
    void renderLitRegion(frame::FrameContext& ctx);

    // Adds the light's maps, weighted, into its visibility.
    void evaluate(frame::FrameContext& ctx, const LightQuadtree& tree);

    // The light's statistics, summed (or maxed) over lights.
    void addStatistics(frame::FrameContext& ctx, const LightQuadtree& tree,
                       const Refinement& r) const;

    // Whether splitting CELL keeps the light's maps within max_maps.
    bool fitsMapBudget(const LightQuadtree& tree, const QuadtreeCell& cell) const;

    // Metric "error": each of CELLS' estimated error from COUNTS (comparisons() order) over
    // SHADOWED pixels, by its worse diagonal.
    static std::vector<double> cellErrors(const LightQuadtree& tree,
                                          const std::vector<QuadtreeCell>& cells,
                                          const std::vector<CompareResult>& counts,
                                          double shadowed);
    // The bits path: splits CHOSEN of CELLS (cell_tiles_ parallel) within the map budget (a
    // refused one goes to REFUSED), each in the tiles around WHERE it disagrees and the
    // horizon's (horizon_tiles_) within its own; records the
    // tiles where each cell stays a leaf and sets cell_tiles_ to the children's.
    std::vector<QuadtreeCell> splitInTiles(LightQuadtree& tree,
                                           const std::vector<QuadtreeCell>& cells,
                                           const std::vector<size_t>& chosen,
                                           const std::vector<std::vector<std::uint32_t>>& where,
                                           const std::function<void(size_t)>& refused,
                                           bool& budget_hit);
    // Metric "error": splits the CELLS whose estimated error (from COUNTS, in comparisons()
    // order, over SHADOWED pixels) BUDGET chooses, within the map budget; returns the children.
    std::vector<QuadtreeCell> splitByError(LightQuadtree& tree,
                                           const std::vector<QuadtreeCell>& cells,
                                           const std::vector<CompareResult>& counts,
                                           double shadowed, ErrorBudget& budget,
                                           bool& budget_hit) const;

    // Splits the CELLS whose comparisons (COUNTS, in comparisons() order) fail the metric, most
    // disagreeing first so that the map budget goes where it matters; returns their children.
    std::vector<QuadtreeCell> splitCells(LightQuadtree& tree,
                                         const std::vector<QuadtreeCell>& cells,
                                         const std::vector<CompareResult>& counts, double area,
                                         bool& budget_hit) const;

    // A perspective view from the light's centre along its axis, covering every caster as
    // seen from there, and every receiver behind them (section 4.1's reprojection target).
    passes::CameraMatrices lightCentreView(const frame::FrameContext& ctx) const;

    // Renders the samples without a map yet into their layers of maps_ (one pass per level).
    void renderNewMaps(frame::FrameContext& ctx, const LightQuadtree& tree, int level);
    // The lit path: renders views FIRST..N-1 into scratch_ kTestBatch at a time and sets their
    // shadow bits.
    void renderAndTest(frame::FrameContext& ctx, int first, int n);

    // Chooses map_size_ for the current light (max_texel) and sizes the map batches to it.
    void chooseMapSize(const frame::FrameContext& ctx);

    // Grows maps_ to at least N layers, keeping its first FILLED maps.
    void reserveMaps(int filled, int n);

    // Copies scratch layers 0..COUNT-1 to maps_ layers BASE.. (layer = view index there).
    void copyToMaps(int base, int count);

    // Adds the weighted tests of BATCH's COUNT views from VIEW_BASE to the bound visibility.
    void addToVisibility(frame::FrameContext& ctx, const passes::ShadowMapBatch& batch,
                         int view_base, int count);

    // The unnormalised weight of a sample created at DEPTH (eq. 5/6), or 1.
    float sampleWeight(const LightQuadtree& tree, int depth) const;

    bool error_metric_;
    double target_error_;
    double epsilon_;
    bool screen_metric_;
    double tile_epsilon_;
    bool light_centre_;
    int max_depth_;
    int max_maps_;
    LightQuadtree::Weighting weighting_;
    bool accumulate_path_;
    bool rss_estimate_;
    bool bits_storage_;    // storage "auto"
    bool skip_lit_;        // the lit path: pixels no caster can shadow are not tested
    double shadowed_ = 0;  // the bits path: pixels any root corner shadows, this light
    bool vertex_layer_ = false;
    Subdivision subdivision_;
    bool jitter_;
    unsigned seed_;
    double max_texel_;
    SamplingSettings settings_;  // settings_.map_size: the largest map
    int map_size_ = 0;           // the current light's maps' side (chooseMapSize)
    CompareSettings compare_;
    std::unique_ptr<passes::ShadowMapBatch> maps_, scratch_;
    std::unique_ptr<passes::ShadowAccumulate> accumulate_;
    std::unique_ptr<MapCompare> map_compare_;
    std::unique_ptr<LitBits> lit_bits_;                    // the lit path's
    std::unique_ptr<passes::DistancePyramid> region_;      // the lit path's casters from the centre
    std::unique_ptr<passes::LightDepthPass> region_pass_;  // their distances into it
    std::unique_ptr<passes::GBuffer> light_view_;          // receivers seen from the light's centre
    passes::SampleViewBuffer views_buffer_;
    // The lit path's screen tiles (refine_tile) for the current light: the comparison pixels'
    // tiles, the tiles of the level's cells (parallel to them), of each view (where it is
    // tested) and of each cell where it stays a leaf (where its corners are weighted).
    int refine_tile_ = 0;
    std::optional<ScreenTiles> tiles_;
    std::vector<std::uint32_t> tile_of_;
    std::vector<TileMask> cell_tiles_, view_tiles_;
    TileMask horizon_tiles_;  // where a caster's own surface cuts the light: every split's
    std::vector<TiledLeaf> tiled_leaves_;
    std::vector<passes::SampleView> views_;
};

}  // namespace penumbra::techniques::adaptive
