// The `bitmask` technique's class, shared by its files: bitmask.cpp (parameters, validation,
// resources, the order of passes) and pixel_passes.cpp (the per-pixel classify, level
// smoothing and visibility passes over the search areas, and the statistics).
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "renderer/gl/handles.h"
#include "renderer/gl/program.h"
#include "renderer/passes/cover_depth.h"
#include "renderer/passes/fullscreen.h"
#include "renderer/passes/light_windows.h"
#include "renderer/techniques/bitmask/budget_map.h"
#include "renderer/techniques/bitmask/depth_ranges.h"
#include "renderer/techniques/bitmask/loq_targets.h"
#include "renderer/techniques/bitmask/microrects.h"
#include "renderer/techniques/bitmask/neighbour_depths.h"
#include "renderer/techniques/bitmask/sample_pattern.h"
#include "renderer/techniques/param_keys.h"
#include "renderer/techniques/technique.h"

namespace penumbra::techniques::bitmask {

enum class Occluders { Micropatch, Microquad, Microrect };
enum class Visibility { Bitmask, Area };
enum class RectFit { Bounds, Coverage };
enum class Peel { Nearest, OthersFirst };

// ACCEL in the shaders is the enum's index: 0 hsm, 1 mssm, 2 ysm (bitmask/search.glsl).
inline constexpr EnumKey<Accel, 3> kAccel{"accel", {"hsm", "mssm", "ysm"}};
inline constexpr EnumKey<Occluders, 3> kOccluders{"occluders",
                                                  {"micropatch", "microquad", "microrect"}};
inline constexpr EnumKey<Visibility, 2> kVisibility{"visibility", {"bitmask", "area"}};
inline constexpr EnumKey<RectFit, 2> kRectFit{"rect_fit", {"bounds", "coverage"}};

inline constexpr FloatKey kSplit{"split"};
inline constexpr IntKey kYsmSize{"ysm_size"};
inline constexpr IntKey kBits{"bits"};
inline constexpr BoolKey kGapFill{"gap_fill"};
inline constexpr FloatKey kGapRatio{"gap_ratio"};
inline constexpr IntKey kLayers{"layers"};
inline constexpr EnumKey<Peel, 2> kPeel{"peel", {"nearest", "others_first"}};
inline constexpr IntKey kBudget{"budget"};
inline constexpr BoolKey kBudgetFalloff{"budget_falloff"};
inline constexpr IntKey kBudgetEdge{"budget_edge"};
inline constexpr TextKey kBudgetMap{"budget_map"};
inline constexpr BoolKey kSmooth{"smooth"};
inline constexpr IntKey kSmoothRadius{"smooth_radius"};
inline constexpr FloatKey kDepthTolerance{"depth_tolerance"};
inline constexpr IntKey kRefineSteps{"refine_steps"};
inline constexpr BoolKey kGrowQuery{"grow_query"};

inline constexpr std::array kBitmaskParams = {
    intParam(kMapSize, 1024, 16, 4096, "light depth map width and height (a power of two)")
        .uniform()
        .limitedBy(GlLimit::MaxTextureSize),
    enumParam(kAccel, Accel::Ysm,
              "search-area depth ranges: min/max pyramid, multi-scale map, or their hybrid")
        .define(),
    intParam(kYsmSize, 256, 16, 4096, "the YSM's MSSM part: width and height (a power of two)")
        .limitedBy(GlLimit::MaxTextureSize),
    enumParam(kOccluders, Occluders::Microrect,
              "micro-occluders: microrects merged per level (5.2), texels, or quads between "
              "texel centres (bitmask only)"),
    enumParam(kRectFit, RectFit::Coverage,
              "microrects' extent: the bounding rectangle of what they merged (the paper), or "
              "that rectangle shrunk to the area of the caster texels inside it, about their "
              "mean (coarse levels overestimate less)"),
    floatParam(kSplit, 0.0625, 0.0, 1.0,
               "a microrect whose farthest caster texel would shadow more than this fraction of "
               "the light's side away from where its nearest depth puts it is replaced by the "
               "finer level's microrects under it (0: never, the paper)")
        .uniform(),
    enumParam(kVisibility, Visibility::Bitmask,
              "occlusion bitmask of light samples, or summed back-projected area"),
    intParam(kBits, 256, 64, 256, "light samples in the bitmask: 64 (8x8), 128 or 256 (16x16)"),
    enumParam(kPattern, Pattern::Jittered, "light sample pattern"),
    intParam(kSeed, 1, 0, 1 << 30, "seed of the jittered or random pattern"),
    boolParam(kGapFill, true, "extend micropatches towards farther neighbours (no light leaks)")
        .define(),
    floatParam(kGapRatio, 1.5, 0.0, 1000.0,
               "gap filling reaches only a neighbour less than this many times farther from the "
               "light (0: any, as the papers; a far one is seldom joined to the near one)")
        .uniform(),
    intParam(kLayers, 2, 1, 2,
             "depth layers back-projected: 1, the casters' surface the light's centre sees (the "
             "paper); 2, also the nearest surface behind it (depth peeling), which the light's "
             "edges see under a caster's silhouette (bitmask only)")
        .define(),
    enumParam(kPeel, Peel::OthersFirst,
              "layers 2: the far layer holds the nearest caster surface behind the map's, or "
              "another object's where there is one before the map object's own far side"),
    intParam(
        kBudget, 12, 0, 64,
        "b_mo: at most b_mo x b_mo micro-occluders per pixel and layer at the chosen level (0 = "
        "unlimited: level 0 up to 64 texels per axis, coarser beyond; else >= 2); blending "
        "also back-projects the finer floor level")
        .uniform(),
    boolParam(kBudgetFalloff, false,
              "budget map: b_mo falls from `budget` at the centre to `budget_edge` at corners")
        .uniform(),
    intParam(kBudgetEdge, 5, 2, 64,
             "b_mo at the image corners with budget_falloff, where budget_map is 0")
        .uniform(),
    stringParam(kBudgetMap, "",
                "budget map image (.png or .exr, relative to the scene file): its first channel "
                "v in [0, 1], stretched over the image, sets b_mo = budget_edge + v (budget - "
                "budget_edge)"),
    boolParam(kSmooth, true,
              "bilateral-filter the fractional level and blend floor/ceiling levels (4.2)"),
    intParam(kSmoothRadius, 6, 1, 32, "half width of the bilateral filter in pixels")
        .uniform("u_radius"),
    floatParam(kDepthTolerance, 0.03, 0.0, 1.0,
               "relative view-depth step where the filter stops (a depth discontinuity)")
        .uniform(),
    intParam(kRefineSteps, 4, 0, 16, "search-area refinements with the area's depth range")
        .uniform(),
    boolParam(kGrowQuery, true,
              "grow depth-range queries to the budget level's texels (section 6, Fig. 7)")
        .uniform(),
    floatParam(kNormalOffset, 1.5, 0.0, 16.0,
               "receiver offset along its normal, in light-map texels (against acne)")
        .uniform(),
    floatParam(kDepthBias, 0.003, 0.0, 0.5,
               "a micro-occluder shadows a receiver only when nearer by this fraction of its "
               "depth")
        .uniform(),
};

class Bitmask final : public Technique {
public:
    explicit Bitmask(const Params& p);

    void readInputs(const scene::Scene& scene) override;
    void prepare(const gl::ContextInfo&, const passes::GpuScene& scene) override;
    void render(frame::FrameContext& ctx) override;

    std::vector<DiagnosticChannel> diagnostics() const override {
        using C = DiagnosticChannel::Combine;
        return {{"level", C::Max}, {"budget", C::Max}, {"occluders", C::Sum}, {"class", C::Max}};
    }

private:
    // The uniforms and textures of search.glsl.
    void bindSearch(const frame::FrameContext& ctx, const gl::Program& p,
                    const scene::RectLight& light, const passes::LightWindow& window);

    void classify(frame::FrameContext& ctx, const scene::RectLight& light,
                  const passes::LightWindow& window, bool shadowed);

    // The separable bilateral filter: horizontal into the spare LOQ map, vertical back.
    void smoothLoq(frame::FrameContext& ctx);

    void visibility(frame::FrameContext& ctx, const scene::RectLight& light,
                    const passes::LightWindow& window);

    // Table 2 of the paper: share of pixels that back-project, mean and standard deviation of
    // the micro-occluders each of them back-projects (sums kept over lights).
    void addStatistics(frame::FrameContext& ctx, int width, int height);

    Params params_;
    int map_size_;
    Accel accel_;
    int ysm_size_;
    bool microrects_, microquads_;
    bool gap_fill_;
    bool use_bitmask_;
    int bits_;
    Pattern pattern_;
    std::uint32_t seed_;
    bool far_layer_;  // layers 2
    // Some object casts, receives and is convex (passes::GpuModel::convex): the maps carry object
    // ids, so such a receiver leaves out micro-occluders of its own object alone (OWN_IDS)
    bool own_ids_ = false;
    int budget_;
    std::string budget_map_file_;
    std::optional<BudgetMap> budget_map_;  // read by readInputs()
    bool smooth_;
    std::unique_ptr<DepthRanges> ranges_;
    std::unique_ptr<LoqTargets> targets_;
    std::unique_ptr<MicroRects> rects_;
    std::unique_ptr<MicroRects> far_rects_;  // layers 2 with microrects
    // gap_fill: each level's distances with their vertical neighbours', the map's (not with
    // microquads, which read the map their own way) and the far layer's
    std::unique_ptr<NeighbourDepths> neighbours_, far_neighbours_;
    gl::Texture receives_, samples_, edges_, budget_texture_;
    gl::Buffer masks_;  // the half-plane tables
    gl::Program classify_, smooth_program_, visibility_;
    gl::Program visibility_cover_;  // visibility.frag's COVER 1: the lit and umbra pixels
    passes::CoverDepth cover_depth_{"bitmask cover"};  // the pixels visibility_cover_ settled
    gl::Buffer stats_;
    passes::Fullscreen fullscreen_;
};

}  // namespace penumbra::techniques::bitmask
