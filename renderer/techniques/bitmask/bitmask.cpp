// `bitmask`: receiver-driven soft shadow mapping with occlusion bitmasks and smooth quality
// scaling (Schwarz & Stamminger 2007, 2008). Per pixel a search area in a light depth map,
// refined with its depth range (HSM, MSSM or YSM); micropatches of a budget-chosen level
// back-projected onto the light into a bitmask of light samples (or summed as area).
#include "renderer/techniques/bitmask/bitmask.h"
#include "glsl/techniques/bitmask/bindings.glsl"

#include <cstdint>
#include <string>

#include "renderer/core/error.h"
#include "renderer/core/memory_limit.h"
#include "renderer/gl/param_uniforms.h"
#include "renderer/techniques/bitmask/mask_textures.h"
#include "renderer/techniques/registry_entries.h"

namespace penumbra::techniques {
namespace bitmask {
namespace {

bool isPowerOfTwo(int n) {
    return n > 0 && (n & (n - 1)) == 0;
}

}  // namespace

Bitmask::Bitmask(const Params& p)
    : params_(p),
      map_size_(p.get(kMapSize)),
      accel_(p.getEnum(kAccel)),
      ysm_size_(p.get(kYsmSize)),
      microrects_(p.getEnum(kOccluders) == Occluders::Microrect),
      microquads_(p.getEnum(kOccluders) == Occluders::Microquad),
      gap_fill_(p.get(kGapFill)),
      use_bitmask_(p.getEnum(kVisibility) == Visibility::Bitmask),
      bits_(p.get(kBits)),
      pattern_(p.getEnum(bitmask::kPattern)),
      seed_(static_cast<std::uint32_t>(p.get(kSeed))),
      far_layer_(p.get(kLayers) == 2),
      budget_(p.get(kBudget)),
      budget_map_file_(p.get(kBudgetMap)),
      smooth_(p.get(kSmooth)) {
    if (!isPowerOfTwo(map_size_))
        throw InputError("technique.map_size: must be a power of two, got " +
                         std::to_string(map_size_));
    if (!isPowerOfTwo(ysm_size_) || ysm_size_ > map_size_)
        throw InputError("technique.ysm_size: must be a power of two up to map_size, got " +
                         std::to_string(ysm_size_));
    if (accel_ == Accel::Mssm && map_size_ > 2048)
        throw InputError(
            "technique.map_size: at most 2048 with accel \"mssm\" (one RG32F map_size^2 "
            "layer per level: 352 MB at 2048); use \"ysm\"");
    bitmask::sampleGrid(bits_);  // validates technique.bits
    if (microquads_ && !use_bitmask_)
        throw InputError("technique.occluders: microquad needs visibility \"bitmask\"");
    // Summed areas would count the far layer's back-projections again behind the front's.
    if (far_layer_ && !use_bitmask_)
        throw InputError(
            "technique.layers: 2 (the default) needs visibility \"bitmask\"; with \"area\" "
            "set layers 1");
    if (budget_ == 1) throw InputError("technique.budget: must be 0 (unlimited) or >= 2");
    // An unlimited budget uses level 0 everywhere: nothing to smooth or blend (Table 2).
    if (budget_ == 0) smooth_ = false;
}

void Bitmask::readInputs(const scene::Scene& scene) {
    if (!budget_map_file_.empty())
        budget_map_ = bitmask::readBudgetMap(scene.path, budget_map_file_);
}

void Bitmask::prepare(const gl::ContextInfo&, const passes::GpuScene& scene) {
    // Per object id: (receives, casts, convex, 0), 255 for yes.
    std::vector<std::uint8_t> roles;
    own_ids_ = false;
    for (const auto& o : scene.objects()) {
        const auto i = 4 * static_cast<size_t>(o.id);
        roles.resize(std::max(roles.size(), i + 4), 0);
        const bool receives = scene::receivesShadow(o.shadow), casts = scene::castsShadow(o.shadow);
        const bool convex = receives && casts && o.model->convex;
        roles[i] = receives ? 255 : 0;
        roles[i + 1] = casts ? 255 : 0;
        roles[i + 2] = convex ? 255 : 0;
        own_ids_ = own_ids_ || convex;
    }
    // Microquads read the map their own way: no ids there. Gap filling's neighbour depths pack
    // an id in 8 bits (neighbours.comp): ids below 255.
    own_ids_ = own_ids_ && !microquads_ && scene.objects().size() < 255;
    if (roles.empty()) roles = {0, 0, 0, 0};
    const int ids = static_cast<int>(roles.size() / 4);
    receives_ = gl::createTexture2D(GL_RGBA8, ids, 1, "bitmask object roles");
    glTextureSubImage2D(receives_.id(), 0, 0, 0, ids, 1, GL_RGBA, GL_UNSIGNED_BYTE, roles.data());
    ranges_ = std::make_unique<DepthRanges>(map_size_, accel_, ysm_size_, far_layer_, own_ids_,
                                            params_.getEnum(kPeel) == Peel::OthersFirst);
    if (use_bitmask_) {
        const auto points = bitmask::samplePoints(bits_, pattern_, seed_);
        masks_ = bitmask::halfPlaneBuffer(points);
        samples_ = bitmask::pointTexture(points);
        if (microquads_) edges_ = bitmask::edgeTexture(points);
    }
    const bool fit = params_.getEnum(kRectFit) == RectFit::Coverage;
    if (microrects_) rects_ = std::make_unique<bitmask::MicroRects>(map_size_, own_ids_, fit);
    if (microrects_ && far_layer_)
        far_rects_ = std::make_unique<bitmask::MicroRects>(map_size_, own_ids_, fit);
    if (gap_fill_ && !microquads_)
        neighbours_ = std::make_unique<bitmask::NeighbourDepths>(map_size_, own_ids_);
    if (gap_fill_ && far_layer_)
        far_neighbours_ = std::make_unique<bitmask::NeighbourDepths>(map_size_, own_ids_);
    if (budget_map_) budget_texture_ = bitmask::uploadBudgetMap(*budget_map_);
    // ACCEL and GAP_FILL from the table; the rest follow from several parameters.
    gl::Defines defines = gl::paramDefines(kBitmaskParams, params_);
    defines.insert(defines.end(), {{"BITMASK", use_bitmask_ ? "1" : "0"},
                                   {"MICRORECTS", microrects_ ? "1" : "0"},
                                   {"MICROQUADS", microquads_ ? "1" : "0"},
                                   {"OWN_IDS", own_ids_ ? "1" : "0"},
                                   {"BLEND", smooth_ ? "1" : "0"}});
    classify_ =
        gl::buildProgram("bitmask classify",
                         {"passes/fullscreen.vert", "techniques/bitmask/classify.frag"}, defines);
    smooth_program_ = gl::buildProgram(
        "bitmask loq smooth", {"passes/fullscreen.vert", "techniques/bitmask/loq_smooth.frag"});
    visibility_ =
        gl::buildProgram("bitmask visibility",
                         {"passes/fullscreen.vert", "techniques/bitmask/visibility.frag"}, defines);
    defines.push_back({"COVER", "1"});
    visibility_cover_ =
        gl::buildProgram("bitmask visibility cover",
                         {"passes/fullscreen.vert", "techniques/bitmask/visibility.frag"}, defines);
    stats_ = gl::createBuffer("bitmask statistics");
    glNamedBufferStorage(stats_.id(), 6 * sizeof(std::uint32_t), nullptr, GL_DYNAMIC_STORAGE_BIT);
}

void Bitmask::render(frame::FrameContext& ctx) {
    const scene::RectLight& light = ctx.currentLight();
    const passes::LightWindow window = passes::occluderWindow(light, ctx.gpu.casterBoxes());
    const int width = ctx.gbuffer.width(), height = ctx.gbuffer.height();
    if (!targets_ || targets_->width() != width || targets_->height() != height)
        targets_ = std::make_unique<bitmask::LoqTargets>(width, height);
    const bool shadowed = !window.empty();
    if (shadowed) {
        ctx.pass("bitmask_shadow_map",
                 [&] { ranges_->renderMap(ctx.gpu, light, window.viewProj(light)); });
        if (far_layer_)
            ctx.pass("bitmask_far_layer",
                     [&] { ranges_->renderFarLayer(ctx.gpu, light, window.viewProj(light)); });
        ctx.pass("bitmask_hsm", [&] { ranges_->buildHsm(); });
        if (accel_ != Accel::Hsm)
            ctx.pass(accel_ == Accel::Ysm ? "bitmask_ysm" : "bitmask_mssm",
                     [&] { ranges_->buildMssm(); });
        if (microrects_)
            ctx.pass("bitmask_microrects", [&] {
                rects_->build(ranges_->hsm(), own_ids_ ? &ranges_->hsmOwners() : nullptr);
            });
        if (far_rects_)
            ctx.pass("bitmask_far_microrects", [&] {
                far_rects_->build(ranges_->farLayer(), own_ids_ ? &ranges_->farOwners() : nullptr);
            });
        if (neighbours_)
            ctx.pass("bitmask_neighbours", [&] {
                neighbours_->build(ranges_->hsm(), rects_ ? &rects_->depth() : nullptr,
                                   own_ids_ ? &ranges_->hsmOwners() : nullptr);
            });
        if (far_neighbours_)
            ctx.pass("bitmask_far_neighbours", [&] {
                far_neighbours_->build(ranges_->farLayer(),
                                       far_rects_ ? &far_rects_->depth() : nullptr,
                                       own_ids_ ? &ranges_->farOwners() : nullptr);
            });
    }
    ctx.pass("bitmask_classify", [&] { classify(ctx, light, window, shadowed); });
    if (smooth_) ctx.pass("bitmask_smooth", [&] { smoothLoq(ctx); });
    const std::uint32_t zero[6] = {0, 0, 0, 0, 0, 0};
    glNamedBufferSubData(stats_.id(), 0, sizeof(zero), zero);
    ctx.pass("bitmask_visibility", [&] { visibility(ctx, light, window); });
    addStatistics(ctx, width, height);
}

}  // namespace bitmask

const TechniqueInfo kBitmaskTechnique = {
    "bitmask",
    "receiver-driven soft shadow mapping (Schwarz & Stamminger 2007/2008): micropatches "
    "back-projected into occlusion bitmasks, budget levels blended smoothly",
    bitmask::kBitmaskParams,
    [](const Params& p) -> std::unique_ptr<Technique> {
        return std::make_unique<bitmask::Bitmask>(p);
    },
    nullptr,
    // The light depth map with its depth ranges (HSM and MSSM), and the YSM.
    [](const Params& p, std::uint64_t) {
        const auto m = static_cast<std::uint64_t>(p.get(kMapSize));
        const auto ysm = static_cast<std::uint64_t>(p.get(bitmask::kYsmSize));
        MemoryTerms terms{{"technique.map_size", "the light depth map and its depth ranges",
                           saturatingProduct({m, m, 4 + 11 + 11})},
                          {"technique.ysm_size", "the YSM", saturatingProduct({ysm, ysm, 11})}};
        // Its pyramid (RG32F mips) and, with microrects, theirs (RGBA32F and RG32F, levels 1..).
        const bool far = p.get(bitmask::kLayers) == 2;
        if (far)
            terms.push_back({"technique.layers", "the far layer's depth ranges and microrects",
                             saturatingProduct({m, m, 11 + 8})});
        // Each layer's owners (RG32F mips), where a convex object casts and receives: counted
        // always, as the scene is not known here.
        terms.push_back({"technique.map_size", "the light maps' object ids",
                         saturatingProduct({m, m, 11, far ? 2u : 1u})});
        // The microrects' fit: a summed-area table of the casters (RGBA32UI), per layer.
        if (p.getEnum(bitmask::kOccluders) == bitmask::Occluders::Microrect &&
            p.getEnum(bitmask::kRectFit) == bitmask::RectFit::Coverage)
            terms.push_back({"technique.rect_fit", "the casters' summed-area tables",
                             saturatingProduct({m + 1, m + 1, 16, far ? 2u : 1u})});
        // Gap filling's neighbour depths (RGBA32F mips), per layer that has them: the map's
        // only without microquads (they read the map their own way), the far layer's always.
        const bool quads = p.getEnum(bitmask::kOccluders) == bitmask::Occluders::Microquad;
        const std::uint64_t gap_layers = (quads ? 0u : 1u) + (far ? 1u : 0u);
        if (p.get(bitmask::kGapFill) && gap_layers > 0)
            terms.push_back({"technique.gap_fill", "the micro-occluders' neighbour depths",
                             saturatingProduct({m, m, 22, gap_layers})});
        return terms;
    }};

}  // namespace penumbra::techniques
