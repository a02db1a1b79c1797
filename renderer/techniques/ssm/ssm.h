// The `ssm` technique's class, shared by its files: ssm.cpp (parameters, resources, the order
// of passes), micro_patch_splat.cpp (occluder micro-patches into soft shadow maps) and
// soft_shadow_lookup.cpp (the receivers' lookup into them).
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "renderer/gl/dynamic_buffer.h"
#include "renderer/gl/handles.h"
#include "renderer/gl/program.h"
#include "renderer/passes/cover_depth.h"
#include "renderer/passes/fullscreen.h"
#include "renderer/passes/light_depth.h"
#include "renderer/passes/light_windows.h"
#include "renderer/techniques/param_keys.h"
#include "renderer/techniques/ssm/micro_patches.h"
#include "renderer/techniques/ssm/receiver_layers.h"
#include "renderer/techniques/ssm/targets.h"
#include "renderer/techniques/technique.h"

namespace penumbra::techniques::ssm {

using passes::LightWindow;

enum class Precision { Fp32, Fp16 };
enum class PatchPath { Gpu, Cpu };
enum class Accumulate { Samples, Area };
enum class FarSide { Second, Farthest };
inline constexpr EnumKey<Precision, 2> kPrecision{"precision", {"fp32", "fp16"}};
inline constexpr EnumKey<PatchPath, 2> kPath{"path", {"gpu", "cpu"}};
inline constexpr EnumKey<Accumulate, 2> kAccumulate{"accumulate", {"samples", "area"}};
inline constexpr EnumKey<FarSide, 2> kFarSide{"far_side", {"second", "farthest"}};

inline constexpr IntKey kSsmSize{"ssm_size"};
inline constexpr BoolKey kTwoSided{"two_sided"};
inline constexpr BoolKey kClip{"clip"};
inline constexpr IntKey kLayers{"layers"};
inline constexpr FloatKey kLod{"lod"};
inline constexpr FloatKey kLodDepth{"lod_depth"};
inline constexpr FloatKey kFarReach{"far_reach"};
inline constexpr FloatKey kSeal{"seal"};

inline constexpr std::array kSsmParams = {
    intParam(kMapSize, 256, 16, 4096, "occluder map width and height in texels")
        .uniform()
        .limitedBy(GlLimit::MaxTextureSize),
    intParam(kSsmSize, 256, 16, 4096, "soft shadow map (and receiver map) width and height")
        .uniform("u_ssm_res")
        .limitedBy(GlLimit::MaxTextureSize),
    enumParam(kPrecision, Precision::Fp32,
              "soft-shadow-map blending precision (fp16 reproduces the paper's Appendix A)"),
    boolParam(kTwoSided, true, "also splat the far occluder surfaces (far_side) from a second map")
        .define(),
    floatParam(kSeal, 0.25, 0.0, 2.0,
               "accumulate=samples: grow each micro-patch by this many texels toward its own "
               "object's neighbours, so that their back-projections overlap instead of leaving "
               "gaps (the union counts an overlap once); 0: off")
        .uniform(),
    enumParam(kFarSide, FarSide::Second,
              "two_sided's far surfaces: second, each texel's nearest caster surface beyond the "
              "front one by depth_bias (a box's hidden walls, not the caster floor beneath it); "
              "farthest, the paper's (3.5)"),
    enumParam(kPath, PatchPath::Gpu,
              "gpu: micro-patch list compacted on the GPU, drawn indirect; cpu: read back (4.1)"),
    boolParam(kClip, true,
              "fit each penumbra quad to the farthest receiver under it, and cull it when none")
        .define(),
    floatParam(kDepthBias, 0.002, 0.0, 0.5,
               "a micro-patch shadows a receiver only when nearer by this fraction of its depth")
        .uniform(),
    floatParam(kFarReach, 0.0, 0.0, 64.0,
               "two_sided: a far-side patch spares the receivers within this many times its "
               "largest depth step to a neighbour (a steep wall's foot); 0: off")
        .uniform(),
    intParam(kLayers, 4, 1, 8,
             "receiver layers peeled from the light's centre, one soft shadow map each; 1 is "
             "the paper: objects of role both occlude only and the receivers are the "
             "role-receiver objects"),
    floatParam(kLod, 4.0, 0.0, 64.0,
               "merge 2x2 micro-patches of one object (level by level) where the penumbra quad "
               "grows on each side by at least this many merged patch widths; 0: off")
        .uniform(),
    floatParam(kLodDepth, 0.005, 0.0, 1.0,
               "merged micro-patches' depths span at most this fraction of their distance from "
               "the light (accumulate=samples: around the plane through the block, so a tilted "
               "surface merges too)")
        .uniform(),
    enumParam(kAccumulate, Accumulate::Samples,
              "samples: each texel keeps which of 256 light samples some micro-patch hides (the "
              "union, both sides in one mask); area: the paper's sum of back-projected areas "
              "(3.4), overlapping patches counted twice (5.1.2)"),
};

// `lod` merges blocks of at most 2^kMaxLodLevel micro-patches a side: splat.frag counts a
// block's micro-patches one by one for receivers near it in depth.
inline constexpr int kMaxLodLevel = 3;

// ssm splats each of its map_size^2 micro-patches over up to ssm_size^2 texels: refused when
// map_size x ssm_size exceeds this (the default 256 x 256 is 2^16).
inline constexpr std::uint64_t kMaxSplatProduct = std::uint64_t{1} << 21;

// Occluder maps a frame renders: the front; two_sided's far side (far_side); with
// far_side=second and accumulate=samples a third, the farthest surface beyond the second (a
// lower plate under two upper ones), which the union may add where the sum would count it twice.
inline int occluderMapCount(bool two_sided, bool samples, bool second) {
    return !two_sided ? 1 : second && samples ? 3 : 2;
}
// Soft shadow maps kept: one per side with accumulate=area and two_sided, else one (a sample
// mask takes every side's union).
inline int softMapCount(bool two_sided, bool samples) {
    return two_sided && !samples ? 2 : 1;
}

// ssm's largest allocations for the memory budget, and the bound above as a message ("" when
// within it): budget.cpp.
MemoryTerms memoryTerms(const Params& p, std::uint64_t pixels);
std::string splatLimitError(const Params& p);

// glDrawArraysIndirect's command: 4 strip vertices, instances = micro-patches of one class, from
// the list's slot base_instance (read by splat.vert).
struct DrawCommand {
    std::uint32_t vertices, instances, first, base_instance;
};

class Ssm final : public Technique {
public:
    explicit Ssm(const Params& p)
        : params_(p),
          map_size_(p.get(kMapSize)),
          ssm_size_(p.get(kSsmSize)),
          fp16_(p.getEnum(kPrecision) == Precision::Fp16),
          two_sided_(p.get(kTwoSided)),
          cpu_path_(p.getEnum(kPath) == PatchPath::Cpu),
          clip_(p.get(kClip)),
          depth_bias_(static_cast<float>(p.get(kDepthBias))),
          layers_(p.get(kLayers)),
          lod_(p.get(kLod) > 0.0),
          samples_(p.getEnum(kAccumulate) == Accumulate::Samples),
          second_(p.getEnum(kFarSide) == FarSide::Second) {}

    // The receivers: with one layer (the paper) the role-receiver objects only.
    bool receives(scene::ShadowRole role) const {
        return layers_ == 1 ? role == scene::ShadowRole::Receiver : scene::receivesShadow(role);
    }
    passes::GpuScene::Filter receiverFilter() const {
        return layers_ == 1 ? passes::GpuScene::Filter::ReceiversOnly
                            : passes::GpuScene::Filter::Receivers;
    }

    void prepare(const gl::ContextInfo&, const passes::GpuScene& scene) override;
    void render(frame::FrameContext& ctx) override;
    std::vector<DiagnosticChannel> diagnostics() const override {
        return {{"occlusion", DiagnosticChannel::Combine::Max},
                {"layer", DiagnosticChannel::Combine::Max}};
    }

private:
    void prepareReceivers(const passes::GpuScene& scene);
    // The light depth view through window W: linear depth over its range.
    static passes::LightDepthView depthView(const scene::RectLight& light, const LightWindow& w) {
        return {w.viewProj(light), w.near, 1.0f / (w.far - w.near)};
    }

    // The farthest-receiver pyramid of each used receiver layer (receiver_max.comp), level by
    // level: a splat quad into layer k is culled where layer k has no receiver under it.
    void buildReceiverMax();

    // Each used receiver layer's tangent plane per texel (receiver_planes.comp), for the splat's
    // test of a micro-patch over its own object's surface.
    void buildReceiverPlanes(const LightWindow& soft);

    // lod.comp's program and textures when `lod` is on (lod.cpp).
    void prepareLod();
    // The micro-patch level of detail of side SIDE (lod.comp): merged blocks into lod_patches_.
    void buildLod(const scene::RectLight& light, const LightWindow& occ, const LightWindow& soft,
                  int side);
    // The map side SIDE's micro-patches are listed from: lod_patches_ with `lod`, else its depth.
    const gl::Texture& patchSource(int side) const {
        return lod_ ? lod_patches_ : occluder_maps_[size_t(side)]->depth;
    }

    // Lists side SIDE's non-empty occluder texels as its micro-patches on the GPU, in row-major
    // order (deterministic, as the CPU path's), and makes their count the splat's instance
    // count (no readback).
    void compact(const LightWindow& occ, int side);

    // Adds every micro-patch's occlusion of side SIDE into its soft shadow map.
    void splat(const scene::RectLight& light, const LightWindow& occ, const LightWindow& soft,
               int side);

    // The depth side SIDE's occluder map is cleared to: 1 (nearest-first depth test), 0 for the
    // farthest surfaces (greater test).
    float emptyDepth(int side) const { return side == 2 || (side == 1 && !second_) ? 0.0f : 1.0f; }
    int sideCount() const { return occluderMapCount(two_sided_, samples_, second_); }
    static std::string sidePass(const char* name, int side) {
        return std::string(name) + (side == 1 ? "[back]" : side == 2 ? "[far]" : "");
    }
    // Side SIDE's occluder map: the front surfaces, two_sided's far ones (far_side), or the
    // farthest beyond the second.
    void renderOccluderMap(const passes::GpuScene& scene, const scene::RectLight& light,
                           const LightWindow& occ, int side);
    int softMapCount() const { return ssm::softMapCount(two_sided_, samples_); }
    // accumulate=samples: clears the sample masks of the used receiver layers.
    void clearSampleMasks();
    // accumulate=samples: each texel's occlusion from its sample mask (samples_resolve.comp).
    void resolveSamples();
    // Sets the splat's stencil to 1 where a used receiver layer has no receiver (FIRST, after
    // clearing it and writing the layers' receiver depths into its depth) or, with
    // accumulate=samples, where every sample is hidden (splat_done.frag).
    void markDoneTexels(bool first);

    // Projects the soft shadow map(s) onto the receivers: visibility and the occlusion channel.
    void visibility(frame::FrameContext& ctx, const scene::RectLight& light,
                    const LightWindow& soft, bool shadowed);

    Params params_;
    int map_size_, ssm_size_;
    bool fp16_, two_sided_, cpu_path_, clip_;
    float depth_bias_;  // also the peeling's gap (host)
    int layers_;
    bool lod_;
    bool samples_;                                       // accumulate=samples
    bool second_;                                        // far_side=second
    std::unique_ptr<passes::LightDepthPass> peel_pass_;  // far_side=second's
    gl::Texture sample_masks_;  // R32UI array: SSM_SAMPLE_WORDS layers per receiver layer
    gl::Program resolve_program_;
    int used_layers_ = 0;      // receiver layers holding a receiver (this light)
    int receiver_passes_ = 0;  // geometry passes that built them
    std::unique_ptr<passes::LightDepthPass> depth_pass_;
    std::array<gl::Program, ssm::kPatchClasses> splat_programs_;  // per patch class
    gl::Program visibility_program_, max_program_, compact_program_, planes_program_;
    // The visibility pass's cover (COVER 1: the pixels it settles) and its depth buffer
    gl::Program visibility_cover_;
    passes::CoverDepth visibility_cover_depth_{"ssm visibility cover"};
    gl::Program done_program_, fill_depth_program_;  // splat_done.frag, FILL_DEPTH 0 and 1
    // DEPTH24_STENCIL8 array: stencil 1 where the splat has nothing to add; depth the receiver's
    gl::Texture splat_stencil_;
    gl::Texture receiver_max_;
    gl::Texture receiver_planes_;  // RGBA16F array: the receiver layers' normals
    int receiver_levels_ = 1;
    std::vector<std::unique_ptr<passes::LightDepthTarget>> occluder_maps_;
    std::vector<std::unique_ptr<SoftShadowTarget>> soft_maps_;
    std::unique_ptr<ssm::ReceiverLayers> receiver_layers_;
    gl::Texture receives_;
    std::array<gl::Program, 3> lod_programs_;  // per phase of lod.comp
    gl::Texture lod_pyramid_;  // RGBA32F mips: per block nearest, farthest depth, id, mergeable
    gl::Texture lod_patches_;  // RGBA32F: per merged block at its first texel middle depth, level,
                               // nearest depth
    gl::Texture lod_slopes_;   // RG32F: per merged block at its first texel its plane's slopes
    int lod_levels_ = 1;
    gl::Buffer counters_;
    gl::Buffer command_;       // the splat's indirect draw per patch class
    gl::Buffer compact_runs_;  // path=gpu: each class's and run's patch count, then first slot
    int compact_run_ = 16, compact_run_count_ = 0;  // texels per run, runs (compact.comp)
    std::vector<gl::Buffer> gpu_patches_;           // path=gpu: the micro-patch list of each side
    gl::VertexArray empty_vao_;
    gl::DynamicBuffer patches_buffer_{"ssm micro-patches"};
    std::vector<float> scratch_;
    std::vector<ssm::MicroPatch> patches_;
    passes::Fullscreen fullscreen_;
};

}  // namespace penumbra::techniques::ssm
