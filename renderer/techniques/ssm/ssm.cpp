// `ssm`: soft shadow maps (Atty et al. 2006). Occluder micro-patches from a light-centred depth
// map are splatted as penumbra quads into a soft shadow map that the receivers look up; with
// `layers` > 1 one soft shadow map per receiver layer peeled from the light's centre (the
// paper's future work, section 7), so objects that occlude also receive.
#include "renderer/techniques/ssm/ssm.h"
#include "glsl/techniques/ssm/bindings.glsl"

#include <algorithm>
#include <bit>
#include <string>

#include "renderer/core/error.h"
#include "renderer/passes/bindings.h"
#include "renderer/techniques/registry_entries.h"

namespace penumbra::techniques {
namespace ssm {

// The receiving objects' table (receives_), after checking that the scene has occluders and
// receivers.
void Ssm::prepareReceivers(const passes::GpuScene& scene) {
    bool occluders = false, receivers = false;
    std::vector<std::uint8_t> receives;
    for (const auto& o : scene.objects()) {
        occluders |= scene::castsShadow(o.shadow);
        receivers |= this->receives(o.shadow);
        if (static_cast<size_t>(o.id) >= receives.size())
            receives.resize(static_cast<size_t>(o.id) + 1, 0);
        receives[static_cast<size_t>(o.id)] = this->receives(o.shadow) ? 255 : 0;
    }
    if (!occluders)
        throw InputError(
            "technique ssm: no occluders: give some object shadow \"occluder\" or \"both\"");
    if (!receivers)
        throw InputError(layers_ == 1
                             ? "technique ssm: layers 1 (the paper) receives on objects of "
                               "shadow \"receiver\" only and there are none: give some "
                               "object shadow \"receiver\", or use layers > 1"
                             : "technique ssm: no receivers: give some object shadow "
                               "\"receiver\" or \"both\"");
    receives_ =
        gl::createTexture2D(GL_R8, static_cast<int>(receives.size()), 1, "ssm receiving objects");
    glTextureSubImage2D(receives_.id(), 0, 0, 0, static_cast<int>(receives.size()), 1, GL_RED,
                        GL_UNSIGNED_BYTE, receives.data());
}

void Ssm::prepare(const gl::ContextInfo&, const passes::GpuScene& scene) {
    prepareReceivers(scene);
    depth_pass_ = std::make_unique<passes::LightDepthPass>(
        "ssm depth", passes::LightDepthPass::Output::DepthAndIds);
    if (two_sided_ && second_)
        peel_pass_ = std::make_unique<passes::LightDepthPass>("ssm occluder peel",
                                                              "techniques/ssm/occluder_peel.frag");
    for (int c = 0; c < ssm::kPatchClasses; ++c)
        splat_programs_[size_t(c)] = gl::buildProgram(
            "ssm splat", {"techniques/ssm/splat.vert", "techniques/ssm/splat.frag"},
            {{"CLIP", clip_ ? "1" : "0"},
             {"SAMPLES", samples_ ? "1" : "0"},
             {"PATCH_CLASS", std::to_string(c)}});
    if (samples_) {
        resolve_program_ =
            gl::buildProgram("ssm samples resolve", {"techniques/ssm/samples_resolve.comp"},
                             {{"TARGET_FORMAT", fp16_ ? "r16f" : "r32f"}});
        sample_masks_ = gl::createTexture2DArray(GL_R32UI, ssm_size_, ssm_size_,
                                                 layers_ * SSM_SAMPLE_WORDS, "ssm sample masks");
    }
    if (!cpu_path_) {
        compact_program_ = gl::buildProgram("ssm compact", {"techniques/ssm/compact.comp"});
        // Room for every texel of one map per side: the list lives on the GPU only.
        const auto bytes = GLsizeiptr(sizeof(ssm::MicroPatch)) * map_size_ * map_size_;
        gpu_patches_.clear();
        for (int side = 0; side < sideCount(); ++side) {
            gpu_patches_.push_back(gl::createBuffer("ssm micro-patches (gpu)"));
            glNamedBufferStorage(gpu_patches_.back().id(), bytes, nullptr, 0);
        }
        // compact.comp's runs of consecutive texels: at most 65536, at least 16 texels each.
        const int texels = map_size_ * map_size_;
        compact_run_ = std::max(16, (texels + 65535) / 65536);
        compact_run_count_ = (texels + compact_run_ - 1) / compact_run_;
        compact_runs_ = gl::createBuffer("ssm compaction runs");
        glNamedBufferStorage(
            compact_runs_.id(),
            GLsizeiptr(sizeof(std::uint32_t)) * ssm::kPatchClasses * compact_run_count_, nullptr,
            0);
    }
    command_ = gl::createBuffer("ssm splat commands");
    glNamedBufferStorage(command_.id(), sizeof(DrawCommand) * ssm::kPatchClasses, nullptr,
                         GL_DYNAMIC_STORAGE_BIT);
    for (const bool cover : {false, true})
        (cover ? visibility_cover_ : visibility_program_) = gl::buildProgram(
            cover ? "ssm visibility cover" : "ssm visibility",
            {"passes/fullscreen.vert", "techniques/ssm/visibility.frag"},
            {{"TWO_SIDED", softMapCount() == 2 ? "1" : "0"}, {"COVER", cover ? "1" : "0"}});
    occluder_maps_.clear();
    soft_maps_.clear();
    const GLenum format = fp16_ ? GL_R16F : GL_R32F;
    for (int side = 0; side < sideCount(); ++side)
        occluder_maps_.push_back(std::make_unique<passes::LightDepthTarget>(
            map_size_, sidePass("ssm occluder map", side).c_str(), true));
    for (int side = 0; side < softMapCount(); ++side)
        soft_maps_.push_back(std::make_unique<SoftShadowTarget>(
            ssm_size_, layers_, format,
            side ? "ssm soft shadow maps (back)" : "ssm soft shadow maps"));
    // The splat's stencil of finished texels, one layer per receiver layer, on every soft map.
    for (const bool fill : {false, true})
        (fill ? fill_depth_program_ : done_program_) =
            gl::buildProgram(fill ? "ssm splat depth" : "ssm splat done",
                             {"passes/fullscreen.vert", "techniques/ssm/splat_done.frag"},
                             {{"SAMPLES", samples_ ? "1" : "0"}, {"FILL_DEPTH", fill ? "1" : "0"}});
    splat_stencil_ = gl::createTexture2DArray(GL_DEPTH24_STENCIL8, ssm_size_, ssm_size_, layers_,
                                              "ssm splat stencil");
    for (const auto& target : soft_maps_)
        for (int k = 0; k < layers_; ++k) {
            const auto& fbo = target->fbos[size_t(k)];
            glNamedFramebufferTextureLayer(fbo.id(), GL_DEPTH_STENCIL_ATTACHMENT,
                                           splat_stencil_.id(), 0, k);
            passes::checkFramebuffer(fbo, "ssm soft shadow map with the splat's stencil");
        }
    receiver_layers_ = std::make_unique<ssm::ReceiverLayers>(
        ssm_size_, layers_, ssm::ReceiverLayers::buildFor(scene.objects().size()),
        "ssm receiver layers");
    if (clip_) {
        max_program_ = gl::buildProgram("ssm receiver max", {"techniques/ssm/receiver_max.comp"});
        receiver_levels_ = std::bit_width(static_cast<unsigned>(ssm_size_));
        receiver_max_ = gl::createTexture(GL_TEXTURE_2D_ARRAY, "ssm receiver max pyramids");
        glTextureStorage3D(receiver_max_.id(), receiver_levels_, GL_R32F, ssm_size_, ssm_size_,
                           layers_);
        glTextureParameteri(receiver_max_.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
        glTextureParameteri(receiver_max_.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    }
    prepareLod();
    planes_program_ =
        gl::buildProgram("ssm receiver planes", {"techniques/ssm/receiver_planes.comp"});
    receiver_planes_ =
        gl::createTexture2DArray(GL_RGBA16F, ssm_size_, ssm_size_, layers_, "ssm receiver planes");
    counters_ = gl::createBuffer("ssm counters");
    glNamedBufferStorage(counters_.id(), 2 * sizeof(std::uint32_t), nullptr,
                         GL_DYNAMIC_STORAGE_BIT);
    empty_vao_ = gl::createVertexArray("ssm splat");
}

void Ssm::renderOccluderMap(const passes::GpuScene& scene, const scene::RectLight& light,
                            const LightWindow& occ, int side) {
    const auto casters = passes::GpuScene::Filter::Casters;
    if (side == 0 || !second_) {
        occluder_maps_[size_t(side)]->render(scene, *depth_pass_, casters, light,
                                             depthView(light, occ), side == 1);
        return;
    }
    // Side 1: the nearest caster surface at least depth_bias of the farthest depth beyond the
    // front's; side 2: the farthest beyond side 1's.
    glUseProgram(peel_pass_->program().id());
    gl::setUniform(peel_pass_->program(), "u_peel_gap",
                   depth_bias_ * occ.far / (occ.far - occ.near));
    glBindTextureUnit(SSM_UNIT_OCC_PEEL_FRONT, occluder_maps_[size_t(side - 1)]->depth.id());
    occluder_maps_[size_t(side)]->render(scene, *peel_pass_, casters, light, depthView(light, occ),
                                         side == 2);
}

void Ssm::render(frame::FrameContext& ctx) {
    const scene::RectLight& light = ctx.currentLight();
    std::vector<passes::WorldBox> receivers;
    for (const auto& o : ctx.gpu.objects())
        if (receives(o.shadow)) receivers.push_back(o.world_box);
    const LightWindow occ =
        ssm::withNearMargin(passes::occluderWindow(light, ctx.gpu.casterBoxes()));
    const LightWindow soft = ssm::softShadowWindow(light, occ, receivers);
    const bool shadowed = !occ.empty() && !soft.empty();
    const int sides = sideCount();

    if (shadowed) {
        ctx.pass("ssm_occluder_map", [&] {
            for (int side = 0; side < sides; ++side) renderOccluderMap(ctx.gpu, light, occ, side);
        });
        ctx.pass("ssm_receiver_map", [&] {
            // Layers at least depth_bias of the farthest receiver's depth apart.
            const float gap = depth_bias_ * soft.far / (soft.far - soft.near);
            const auto built = receiver_layers_->render(ctx.gpu, receiverFilter(), light,
                                                        depthView(light, soft), gap);
            used_layers_ = built.used;
            receiver_passes_ = built.passes;
            if (clip_) buildReceiverMax();
            if (layers_ > 1) buildReceiverPlanes(soft);
        });
        const std::uint32_t zero[2] = {0, 0};
        glNamedBufferSubData(counters_.id(), 0, sizeof(zero), zero);
        for (int side = 0; side < sides; ++side) {
            if (lod_)
                ctx.pass(sidePass("ssm_lod", side), [&] { buildLod(light, occ, soft, side); });
            if (!cpu_path_) ctx.pass(sidePass("ssm_compact", side), [&] { compact(occ, side); });
            if (cpu_path_)
                ctx.pass(sidePass("ssm_readback", side), [&] {
                    const auto counts =
                        ssm::readMicroPatches(patchSource(side), lod_ ? &lod_slopes_ : nullptr,
                                              map_size_, occ, emptyDepth(side), scratch_, patches_);
                    std::array<DrawCommand, ssm::kPatchClasses> commands{};
                    std::uint32_t first = 0;
                    for (size_t c = 0; c < commands.size(); ++c) {
                        commands[c] = {4, counts[c], 0, first};
                        first += counts[c];
                    }
                    glNamedBufferSubData(command_.id(), 0, sizeof(commands), commands.data());
                    patches_buffer_.upload(std::span<const ssm::MicroPatch>(patches_),
                                           GL_SHADER_STORAGE_BUFFER, SSM_BINDING_PATCHES,
                                           sizeof(ssm::MicroPatch));
                });
            ctx.pass(sidePass("ssm_splat", side), [&] {
                if (samples_ && side == 0) clearSampleMasks();
                splat(light, occ, soft, side);
            });
        }
        if (samples_) ctx.pass("ssm_samples_resolve", [&] { resolveSamples(); });
    }
    ctx.pass("ssm_visibility", [&] { visibility(ctx, light, soft, shadowed); });

    std::uint32_t counts[2] = {0, 0};
    if (shadowed) glGetNamedBufferSubData(counters_.id(), 0, sizeof(counts), counts);
    const double patches = ctx.stats.value("micro_patches", 0.0) + counts[0];
    const double touched = ctx.stats.value("texels_touched", 0.0) + counts[1];
    ctx.stats["micro_patches"] = patches;
    ctx.stats["texels_touched"] = touched;
    ctx.stats["fill_per_micro_patch"] = patches > 0 ? touched / patches : 0.0;
    ctx.stats["receiver_layers"] =
        std::max(ctx.stats.value("receiver_layers", 0), shadowed ? used_layers_ : 0);
    ctx.stats["receiver_passes"] =
        ctx.stats.value("receiver_passes", 0) + (shadowed ? receiver_passes_ : 0);
}

}  // namespace ssm

const TechniqueInfo kSsmTechnique = {
    "ssm",
    "soft shadow maps (Atty et al. 2006): occluder micro-patches splatted as penumbra quads",
    ssm::kSsmParams,
    [](const Params& p) -> std::unique_ptr<Technique> { return std::make_unique<ssm::Ssm>(p); },
    nullptr,
    ssm::memoryTerms,
    ssm::splatLimitError};

}  // namespace penumbra::techniques
