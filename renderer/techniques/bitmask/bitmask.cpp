// `bitmask`: receiver-driven soft shadow mapping with occlusion bitmasks and smooth quality
// scaling (Schwarz & Stamminger 2007, 2008). Per pixel a search area in a light depth map,
// refined with its depth range (HSM, MSSM or YSM); micropatches of a budget-chosen level
// back-projected onto the light into a bitmask of light samples (or summed as area).
#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "glsl/techniques/bitmask/bindings.glsl"
#include "renderer/core/error.h"
#include "renderer/gl/param_uniforms.h"
#include "renderer/gl/program.h"
#include "renderer/passes/fullscreen.h"
#include "renderer/passes/shadow_maps.h"
#include "renderer/techniques/bitmask/budget_map.h"
#include "renderer/techniques/bitmask/depth_ranges.h"
#include "renderer/techniques/bitmask/loq_targets.h"
#include "renderer/techniques/bitmask/mask_textures.h"
#include "renderer/techniques/bitmask/microrects.h"
#include "renderer/techniques/bitmask/sample_pattern.h"
#include "renderer/techniques/registry_entries.h"
#include "renderer/techniques/ssm/light_windows.h"

namespace penumbra::techniques {
namespace {

using bitmask::Accel;
using bitmask::DepthRanges;

enum class Occluders { Micropatch, Microquad, Microrect };
enum class Visibility { Bitmask, Area };

// ACCEL in the shaders is the enum's index: 0 hsm, 1 mssm, 2 ysm (bitmask/search.glsl).
constexpr EnumKey<Accel, 3> kAccel{"accel", {"hsm", "mssm", "ysm"}};
constexpr EnumKey<Occluders, 3> kOccluders{"occluders", {"micropatch", "microquad", "microrect"}};
constexpr EnumKey<Visibility, 2> kVisibility{"visibility", {"bitmask", "area"}};

constexpr std::array kBitmaskParams = {
    intParam("map_size", 1024, 16, 4096, "light depth map width and height (a power of two)")
        .uniform()
        .limitedBy(GlLimit::MaxTextureSize),
    enumParam(kAccel, Accel::Ysm,
              "search-area depth ranges: min/max pyramid, multi-scale map, or their hybrid")
        .define(),
    intParam("ysm_size", 256, 16, 4096, "the YSM's MSSM part: width and height (a power of two)"),
    enumParam(kOccluders, Occluders::Microrect,
              "micro-occluders: microrects merged per level (5.2), texels, or quads between "
              "texel centres (bitmask only)"),
    enumParam(kVisibility, Visibility::Bitmask,
              "occlusion bitmask of light samples, or summed back-projected area"),
    intParam("bits", 256, 64, 256, "light samples in the bitmask: 64 (8x8), 128 or 256 (16x16)"),
    enumParam(bitmask::kPattern, bitmask::Pattern::Jittered, "light sample pattern"),
    intParam("seed", 1, 0, 1 << 30, "seed of the jittered or random pattern"),
    boolParam("gap_fill", true, "extend micropatches towards farther neighbours (no light leaks)")
        .define(),
    intParam("budget", 12, 0, 64,
             "b_mo: at most b_mo x b_mo micro-occluders per pixel at the chosen level (0 = "
             "unlimited: level 0 up to 64 texels per axis, coarser beyond; else >= 2); blending "
             "also back-projects the finer floor level")
        .uniform(),
    boolParam("budget_falloff", false,
              "budget map: b_mo falls from `budget` at the centre to `budget_edge` at corners")
        .uniform(),
    intParam("budget_edge", 5, 2, 64,
             "b_mo at the image corners with budget_falloff, where budget_map is 0")
        .uniform(),
    stringParam("budget_map", "",
                "budget map image (.png or .exr, relative to the scene file): its first channel "
                "v in [0, 1], stretched over the image, sets b_mo = budget_edge + v (budget - "
                "budget_edge)"),
    boolParam("smooth", true,
              "bilateral-filter the fractional level and blend floor/ceiling levels (4.2)"),
    intParam("smooth_radius", 6, 1, 32, "half width of the bilateral filter in pixels")
        .uniform("u_radius"),
    floatParam("depth_tolerance", 0.03, 0.0, 1.0,
               "relative view-depth step where the filter stops (a depth discontinuity)")
        .uniform(),
    intParam("refine_steps", 4, 0, 16, "search-area refinements with the area's depth range")
        .uniform(),
    boolParam("grow_query", true,
              "grow depth-range queries to the budget level's texels (section 6, Fig. 7)")
        .uniform(),
    floatParam("normal_offset", 1.5, 0.0, 16.0,
               "receiver offset along its normal, in light-map texels (against acne)")
        .uniform(),
    floatParam("depth_bias", 0.003, 0.0, 0.5,
               "a micro-occluder shadows a receiver only when nearer by this fraction of its "
               "depth")
        .uniform(),
};

bool isPowerOfTwo(int n) {
    return n > 0 && (n & (n - 1)) == 0;
}

class Bitmask final : public Technique {
public:
    explicit Bitmask(const Params& p)
        : params_(p),
          map_size_(p.getInt("map_size")),
          accel_(p.getEnum(kAccel)),
          ysm_size_(p.getInt("ysm_size")),
          microrects_(p.getEnum(kOccluders) == Occluders::Microrect),
          microquads_(p.getEnum(kOccluders) == Occluders::Microquad),
          use_bitmask_(p.getEnum(kVisibility) == Visibility::Bitmask),
          bits_(p.getInt("bits")),
          pattern_(p.getEnum(bitmask::kPattern)),
          seed_(static_cast<std::uint32_t>(p.getInt("seed"))),
          budget_(p.getInt("budget")),
          budget_map_file_(p.getString("budget_map")),
          smooth_(p.getBool("smooth")) {
        if (!isPowerOfTwo(map_size_))
            throw InputError("technique.map_size: must be a power of two, got " +
                             std::to_string(map_size_));
        if (!isPowerOfTwo(ysm_size_) || ysm_size_ > map_size_)
            throw InputError("technique.ysm_size: must be a power of two up to map_size, got " +
                             std::to_string(ysm_size_));
        if (accel_ == Accel::Mssm && map_size_ > 2048)
            throw InputError(
                "technique.map_size: at most 2048 with accel \"mssm\" (one RG32F map_size^2 "
                "layer per level: 384 MB at 2048); use \"ysm\"");
        bitmask::sampleGrid(bits_);  // validates technique.bits
        if (microquads_ && !use_bitmask_)
            throw InputError("technique.occluders: microquad needs visibility \"bitmask\"");
        if (budget_ == 1) throw InputError("technique.budget: must be 0 (unlimited) or >= 2");
        // An unlimited budget uses level 0 everywhere: nothing to smooth or blend (Table 2).
        if (budget_ == 0) smooth_ = false;
    }

    void readInputs(const scene::Scene& scene) override {
        if (!budget_map_file_.empty())
            budget_map_ = bitmask::readBudgetMap(scene.path, budget_map_file_);
    }

    void prepare(const gl::ContextInfo&, const passes::GpuScene& scene) override {
        // Per object id: (receives, casts), 255 for yes.
        std::vector<std::uint8_t> roles;
        for (const auto& o : scene.objects()) {
            const auto i = 2 * static_cast<size_t>(o.id);
            roles.resize(std::max(roles.size(), i + 2), 0);
            roles[i] = scene::receivesShadow(o.shadow) ? 255 : 0;
            roles[i + 1] = scene::castsShadow(o.shadow) ? 255 : 0;
        }
        if (roles.empty()) roles = {0, 0};
        const int ids = static_cast<int>(roles.size() / 2);
        receives_ = gl::createTexture2D(GL_RG8, ids, 1, "bitmask object roles");
        glTextureSubImage2D(receives_.id(), 0, 0, 0, ids, 1, GL_RG, GL_UNSIGNED_BYTE, roles.data());
        ranges_ = std::make_unique<DepthRanges>(map_size_, accel_, ysm_size_);
        if (use_bitmask_) {
            const auto points = bitmask::samplePoints(bits_, pattern_, seed_);
            masks_ = bitmask::halfPlaneTexture(points);
            samples_ = bitmask::pointTexture(points);
            if (microquads_) edges_ = bitmask::edgeTexture(points);
        }
        if (microrects_) rects_ = std::make_unique<bitmask::MicroRects>(map_size_);
        if (budget_map_) budget_texture_ = bitmask::uploadBudgetMap(*budget_map_);
        // ACCEL and GAP_FILL from the table; the rest follow from several parameters.
        gl::Defines defines = gl::paramDefines(kBitmaskParams, params_);
        defines.insert(defines.end(), {{"BITMASK", use_bitmask_ ? "1" : "0"},
                                       {"MICRORECTS", microrects_ ? "1" : "0"},
                                       {"MICROQUADS", microquads_ ? "1" : "0"},
                                       {"BLEND", smooth_ ? "1" : "0"}});
        classify_ = gl::buildProgram("bitmask classify",
                                     {"passes/fullscreen.vert", "techniques/bitmask/classify.frag"},
                                     defines);
        smooth_program_ = gl::buildProgram(
            "bitmask loq smooth", {"passes/fullscreen.vert", "techniques/bitmask/loq_smooth.frag"});
        visibility_ = gl::buildProgram(
            "bitmask visibility", {"passes/fullscreen.vert", "techniques/bitmask/visibility.frag"},
            defines);
        stats_ = gl::createBuffer("bitmask statistics");
        glNamedBufferStorage(stats_.id(), 6 * sizeof(std::uint32_t), nullptr,
                             GL_DYNAMIC_STORAGE_BIT);
    }

    void render(frame::FrameContext& ctx) override {
        const scene::RectLight& light = ctx.currentLight();
        const ssm::LightWindow window = ssm::occluderWindow(light, ctx.gpu.casterBounds());
        const int width = ctx.gbuffer.width(), height = ctx.gbuffer.height();
        if (!targets_ || targets_->width() != width || targets_->height() != height)
            targets_ = std::make_unique<bitmask::LoqTargets>(width, height);
        const bool shadowed = !window.empty();
        if (shadowed) {
            ctx.pass("bitmask_shadow_map",
                     [&] { ranges_->renderMap(ctx.gpu, light, window.viewProj(light)); });
            ctx.pass("bitmask_hsm", [&] { ranges_->buildHsm(); });
            if (accel_ != Accel::Hsm)
                ctx.pass(accel_ == Accel::Ysm ? "bitmask_ysm" : "bitmask_mssm",
                         [&] { ranges_->buildMssm(); });
            if (microrects_) ctx.pass("bitmask_microrects", [&] { rects_->build(ranges_->hsm()); });
        }
        ctx.pass("bitmask_classify", [&] { classify(ctx, light, window, shadowed); });
        if (smooth_) ctx.pass("bitmask_smooth", [&] { smoothLoq(ctx); });
        const std::uint32_t zero[6] = {0, 0, 0, 0, 0, 0};
        glNamedBufferSubData(stats_.id(), 0, sizeof(zero), zero);
        ctx.pass("bitmask_visibility", [&] { visibility(ctx, light, window); });
        addStatistics(ctx, width, height);
    }

    std::vector<DiagnosticChannel> diagnostics() const override {
        using C = DiagnosticChannel::Combine;
        return {{"level", C::Max}, {"budget", C::Max}, {"occluders", C::Sum}, {"class", C::Max}};
    }

private:
    // The uniforms and textures of search.glsl.
    void bindSearch(const frame::FrameContext& ctx, const gl::Program& p,
                    const scene::RectLight& light, const ssm::LightWindow& window) {
        glBindTextureUnit(BITMASK_UNIT_SEARCH_POSITION, ctx.gbuffer.position().id());
        glBindTextureUnit(BITMASK_UNIT_SEARCH_NORMAL, ctx.gbuffer.normal().id());
        glBindTextureUnit(BITMASK_UNIT_SEARCH_ID, ctx.gbuffer.id().id());
        ctx.gbuffer.bindGeometricNormal();
        glBindTextureUnit(BITMASK_UNIT_SEARCH_RECEIVES, receives_.id());
        glBindTextureUnit(BITMASK_UNIT_SEARCH_HSM, ranges_->hsm().id());
        if (accel_ != Accel::Hsm) glBindTextureUnit(BITMASK_UNIT_SEARCH_MSSM, ranges_->mssm().id());
        gl::setUniform(p, "u_mssm_base", ranges_->mssmBase());
        passes::setLightFrameUniforms(p, light);
        gl::setUniform(p, "u_light_half", 0.5f * light.size);
        gl::setUniform(p, "u_win_lo", window.lo);
        gl::setUniform(p, "u_texel", window.size / static_cast<float>(map_size_));
        gl::setUniform(p, "u_levels", ranges_->levels());
        gl::setUniform(p, "u_near", window.near);
        // map_size, normal_offset, depth_bias; in classify also refine_steps, the budget's and
        // grow_query.
        gl::setParamUniforms(p, kBitmaskParams, params_);
    }

    void classify(frame::FrameContext& ctx, const scene::RectLight& light,
                  const ssm::LightWindow& window, bool shadowed) {
        targets_->bindClassify();
        const float zero[4] = {0, 0, 0, 0}, none[4] = {-1, 0, float(budget_), 0};
        glClearBufferfv(GL_COLOR, 0, zero);
        glClearBufferfv(GL_COLOR, 1, none);
        if (shadowed) {
            const auto& p = classify_;
            glUseProgram(p.id());
            bindSearch(ctx, p, light, window);
            gl::setUniform(p, "u_budget_map_on", budget_texture_ ? 1 : 0);
            if (budget_texture_)
                glBindTextureUnit(BITMASK_UNIT_CLASSIFY_BUDGET_MAP, budget_texture_.id());
            fullscreen_.draw();
            glUseProgram(0);
        }
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
    }

    // The separable bilateral filter: horizontal into the spare LOQ map, vertical back.
    void smoothLoq(frame::FrameContext& ctx) {
        const auto& p = smooth_program_;
        glUseProgram(p.id());
        gl::setParamUniforms(p, kBitmaskParams, params_);  // smooth_radius, depth_tolerance
        glBindTextureUnit(BITMASK_UNIT_SMOOTH_NORMAL, ctx.gbuffer.normal().id());
        for (int pass = 0; pass < 2; ++pass) {
            targets_->bindLoq(pass == 0 ? 1 : 0);
            glBindTextureUnit(BITMASK_UNIT_SMOOTH_LOQ, targets_->loq(pass == 0 ? 0 : 1).id());
            gl::setUniform(p, "u_direction", pass == 0 ? glm::ivec2(1, 0) : glm::ivec2(0, 1));
            fullscreen_.draw();
        }
        glUseProgram(0);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
    }

    void visibility(frame::FrameContext& ctx, const scene::RectLight& light,
                    const ssm::LightWindow& window) {
        ctx.bindOutput();
        glDisable(GL_BLEND);
        glDisable(GL_DEPTH_TEST);
        const auto& p = visibility_;
        glUseProgram(p.id());
        bindSearch(ctx, p, light, window);
        if (use_bitmask_) {
            glBindTextureUnit(BITMASK_UNIT_VISIBILITY_MASKS, masks_.id());
            glBindTextureUnit(BITMASK_UNIT_VISIBILITY_SAMPLES, samples_.id());
            gl::setUniform(p, "u_mask_resolution", bitmask::kTableResolution);
            gl::setUniform(p, "u_sample_count", static_cast<float>(bits_));
        }
        glBindTextureUnit(BITMASK_UNIT_VISIBILITY_AREA, targets_->area().id());
        glBindTextureUnit(BITMASK_UNIT_VISIBILITY_LOQ, targets_->loq(0).id());
        if (microquads_) {
            glBindTextureUnit(BITMASK_UNIT_VISIBILITY_EDGES, edges_.id());
            gl::setUniform(p, "u_edge_angles", bitmask::kEdgeAngles);
            gl::setUniform(p, "u_edge_offsets", bitmask::kEdgeOffsets);
        }
        if (microrects_) {
            glBindTextureUnit(BITMASK_UNIT_VISIBILITY_RECT_EXTENT, rects_->extent().id());
            glBindTextureUnit(BITMASK_UNIT_VISIBILITY_RECT_DEPTH, rects_->depth().id());
        }
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BITMASK_BINDING_VISIBILITY_STATS, stats_.id());
        fullscreen_.draw();
        glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
        glUseProgram(0);
    }

    // Table 2 of the paper: share of pixels that back-project, mean and standard deviation of
    // the micro-occluders each of them back-projects (sums kept over lights).
    void addStatistics(frame::FrameContext& ctx, int width, int height) {
        std::uint32_t s[6] = {0, 0, 0, 0, 0, 0};
        glGetNamedBufferSubData(stats_.id(), 0, sizeof(s), s);
        auto add = [&](const char* key, double v) {
            const double total = ctx.stats.value(key, 0.0) + v;
            ctx.stats[key] = total;
            return total;
        };
        const double pixels = add("pixels", double(width) * double(height));
        const double n = add("backprojecting_pixels", s[0]);
        add("umbra_pixels", s[1]);
        const double sum = add("micro_occluders", double(s[2]) + 4294967296.0 * double(s[3]));
        const double squares =
            add("micro_occluders_squared", double(s[4]) + 4294967296.0 * double(s[5]));
        const double mean = n > 0 ? sum / n : 0.0;
        ctx.stats["backprojecting_share"] = pixels > 0 ? n / pixels : 0.0;
        ctx.stats["micro_occluders_mean"] = mean;
        ctx.stats["micro_occluders_stddev"] =
            n > 0 ? std::sqrt(std::max(squares / n - mean * mean, 0.0)) : 0.0;
    }

    Params params_;
    int map_size_;
    Accel accel_;
    int ysm_size_;
    bool microrects_, microquads_;
    bool use_bitmask_;
    int bits_;
    bitmask::Pattern pattern_;
    std::uint32_t seed_;
    int budget_;
    std::string budget_map_file_;
    std::optional<bitmask::BudgetMap> budget_map_;  // read by readInputs()
    bool smooth_;
    std::unique_ptr<DepthRanges> ranges_;
    std::unique_ptr<bitmask::LoqTargets> targets_;
    std::unique_ptr<bitmask::MicroRects> rects_;
    gl::Texture receives_, masks_, samples_, edges_, budget_texture_;
    gl::Program classify_, smooth_program_, visibility_;
    gl::Buffer stats_;
    passes::Fullscreen fullscreen_;
};

}  // namespace

const TechniqueInfo kBitmaskTechnique = {
    "bitmask",
    "receiver-driven soft shadow mapping (Schwarz & Stamminger 2007/2008): micropatches "
    "back-projected into occlusion bitmasks, budget levels blended smoothly",
    kBitmaskParams,
    [](const Params& p) -> std::unique_ptr<Technique> { return std::make_unique<Bitmask>(p); }};

}  // namespace penumbra::techniques
