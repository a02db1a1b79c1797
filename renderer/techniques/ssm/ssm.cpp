// `ssm`: soft shadow maps (Atty et al. 2006). Occluder micro-patches from a light-centred depth
// map are splatted as penumbra quads into a soft shadow map that the receivers look up; with
// `layers` > 1 one soft shadow map per receiver layer peeled from the light's centre (the
// paper's future work, section 7), so objects that occlude also receive.
#include <algorithm>
#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "glsl/techniques/ssm/bindings.glsl"
#include "renderer/core/error.h"
#include "renderer/gl/dynamic_buffer.h"
#include "renderer/gl/param_uniforms.h"
#include "renderer/passes/bindings.h"
#include "renderer/passes/fullscreen.h"
#include "renderer/passes/shadow_maps.h"
#include "renderer/techniques/registry_entries.h"
#include "renderer/techniques/ssm/light_windows.h"
#include "renderer/techniques/ssm/micro_patches.h"
#include "renderer/techniques/ssm/targets.h"

namespace penumbra::techniques {
namespace {

using ssm::DepthTarget;
using ssm::LightWindow;
using ssm::SoftShadowTarget;

enum class Precision { Fp32, Fp16 };
enum class PatchPath { Gpu, Cpu };
constexpr EnumKey<Precision, 2> kPrecision{"precision", {"fp32", "fp16"}};
constexpr EnumKey<PatchPath, 2> kPath{"path", {"gpu", "cpu"}};

constexpr std::array kSsmParams = {
    intParam("map_size", 256, 16, 4096, "occluder map width and height in texels")
        .uniform()
        .limitedBy(GlLimit::MaxTextureSize),
    intParam("ssm_size", 256, 16, 4096, "soft shadow map (and receiver map) width and height")
        .uniform("u_ssm_res"),
    enumParam(kPrecision, Precision::Fp32,
              "soft-shadow-map blending precision (fp16 reproduces the paper's Appendix A)"),
    boolParam("two_sided", false,
              "also splat the farthest (back) occluder surfaces into a second map, merged by max")
        .define(),
    enumParam(kPath, PatchPath::Gpu,
              "gpu: micro-patch list compacted on the GPU, drawn indirect; cpu: read back (4.1)"),
    boolParam("clip", true,
              "fit each penumbra quad to the farthest receiver under it, and cull it when none")
        .define(),
    floatParam("depth_bias", 0.002, 0.0, 0.5,
               "a micro-patch shadows a receiver only when nearer by this fraction of its depth")
        .uniform(),
    intParam("layers", 4, 1, 8,
             "receiver layers peeled from the light's centre, one soft shadow map each; 1 is "
             "the paper: objects of role both occlude only and the receivers are the "
             "role-receiver objects"),
};

// glDrawArraysIndirect's command: 4 strip vertices, instances = micro-patches.
struct DrawCommand {
    std::uint32_t vertices, instances, first, base_instance;
};

class Ssm final : public Technique {
public:
    explicit Ssm(const Params& p)
        : params_(p),
          map_size_(p.getInt("map_size")),
          ssm_size_(p.getInt("ssm_size")),
          fp16_(p.getEnum(kPrecision) == Precision::Fp16),
          two_sided_(p.getBool("two_sided")),
          cpu_path_(p.getEnum(kPath) == PatchPath::Cpu),
          clip_(p.getBool("clip")),
          depth_bias_(static_cast<float>(p.getFloat("depth_bias"))),
          layers_(p.getInt("layers")) {}

    // The receivers: with one layer (the paper) the role-receiver objects only.
    bool receives(scene::ShadowRole role) const {
        return layers_ == 1 ? role == scene::ShadowRole::Receiver : scene::receivesShadow(role);
    }
    passes::GpuScene::Filter receiverFilter() const {
        return layers_ == 1 ? passes::GpuScene::Filter::ReceiversOnly
                            : passes::GpuScene::Filter::Receivers;
    }

    void prepare(const gl::ContextInfo&, const passes::GpuScene& scene) override {
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
        receives_ = gl::createTexture2D(GL_R8, static_cast<int>(receives.size()), 1,
                                        "ssm receiving objects");
        glTextureSubImage2D(receives_.id(), 0, 0, 0, static_cast<int>(receives.size()), 1, GL_RED,
                            GL_UNSIGNED_BYTE, receives.data());

        depth_program_ = gl::buildProgram(
            "ssm depth", {"techniques/ssm/depth.vert", "techniques/ssm/depth.frag"});
        peel_program_ = gl::buildProgram("ssm receiver layers",
                                         {"techniques/ssm/depth.vert", "techniques/ssm/peel.frag"},
                                         {{"PEEL", "1"}});
        splat_program_ = gl::buildProgram(
            "ssm splat", {"techniques/ssm/splat.vert", "techniques/ssm/splat.frag"},
            {{"CLIP", clip_ ? "1" : "0"}});
        if (!cpu_path_) {
            compact_program_ = gl::buildProgram("ssm compact", {"techniques/ssm/compact.comp"});
            // Room for every texel of one map per side: the list lives on the GPU only.
            const auto bytes = GLsizeiptr(sizeof(ssm::MicroPatch)) * map_size_ * map_size_;
            gpu_patches_.clear();
            for (int side = 0; side < (two_sided_ ? 2 : 1); ++side) {
                gpu_patches_.push_back(gl::createBuffer("ssm micro-patches (gpu)"));
                glNamedBufferStorage(gpu_patches_.back().id(), bytes, nullptr, 0);
            }
            command_ = gl::createBuffer("ssm splat command");
            glNamedBufferStorage(command_.id(), sizeof(DrawCommand), nullptr,
                                 GL_DYNAMIC_STORAGE_BIT);
        }
        visibility_program_ = gl::buildProgram(
            "ssm visibility", {"passes/fullscreen.vert", "techniques/ssm/visibility.frag"},
            {{"TWO_SIDED", two_sided_ ? "1" : "0"}});
        occluder_maps_.clear();
        soft_maps_.clear();
        const GLenum format = fp16_ ? GL_R16F : GL_R32F;
        for (int side = 0; side < (two_sided_ ? 2 : 1); ++side) {
            occluder_maps_.push_back(std::make_unique<DepthTarget>(
                map_size_, side ? "ssm occluder map (back)" : "ssm occluder map", true));
            soft_maps_.push_back(std::make_unique<SoftShadowTarget>(
                ssm_size_, layers_, format,
                side ? "ssm soft shadow maps (back)" : "ssm soft shadow maps"));
        }
        receiver_layers_ =
            std::make_unique<ssm::ReceiverLayers>(ssm_size_, layers_, "ssm receiver layers");
        if (clip_) {
            max_program_ =
                gl::buildProgram("ssm receiver max", {"techniques/ssm/receiver_max.comp"});
            receiver_levels_ = 1;
            while ((ssm_size_ >> receiver_levels_) > 0) ++receiver_levels_;
            receiver_max_ = gl::createTexture(GL_TEXTURE_2D_ARRAY, "ssm receiver max pyramids");
            glTextureStorage3D(receiver_max_.id(), receiver_levels_, GL_R32F, ssm_size_, ssm_size_,
                               layers_);
            glTextureParameteri(receiver_max_.id(), GL_TEXTURE_MIN_FILTER,
                                GL_NEAREST_MIPMAP_NEAREST);
            glTextureParameteri(receiver_max_.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        }
        counters_ = gl::createBuffer("ssm counters");
        glNamedBufferStorage(counters_.id(), 2 * sizeof(std::uint32_t), nullptr,
                             GL_DYNAMIC_STORAGE_BIT);
        empty_vao_ = gl::createVertexArray("ssm splat");
    }

    void render(frame::FrameContext& ctx) override {
        const scene::RectLight& light = ctx.currentLight();
        passes::Bounds receiver_bounds;
        for (const auto& o : ctx.gpu.objects())
            if (receives(o.shadow)) receiver_bounds.extend(o.world_bounds);
        const LightWindow occ = ssm::occluderWindow(light, ctx.gpu.casterBounds());
        const LightWindow soft = ssm::softShadowWindow(light, occ, receiver_bounds);
        const bool shadowed = !occ.empty() && !soft.empty();
        const int sides = two_sided_ ? 2 : 1;

        if (shadowed) {
            ctx.pass("ssm_occluder_map", [&] {
                for (int side = 0; side < sides; ++side)
                    occluder_maps_[size_t(side)]->render(ctx.gpu, depth_program_,
                                                         passes::GpuScene::Filter::Casters,
                                                         occ.viewProj(light), light, occ.near,
                                                         1.0f / (occ.far - occ.near), side == 1);
            });
            ctx.pass("ssm_receiver_map", [&] {
                // Layers at least depth_bias of the farthest receiver's depth apart.
                const float gap = depth_bias_ * soft.far / (soft.far - soft.near);
                used_layers_ = receiver_layers_->render(ctx.gpu, peel_program_, receiverFilter(),
                                                        soft.viewProj(light), light, soft.near,
                                                        1.0f / (soft.far - soft.near), gap);
                if (clip_) buildReceiverMax();
            });
            const std::uint32_t zero[2] = {0, 0};
            glNamedBufferSubData(counters_.id(), 0, sizeof(zero), zero);
            for (int side = 0; side < sides; ++side) {
                if (!cpu_path_)
                    ctx.pass(side ? "ssm_compact[back]" : "ssm_compact",
                             [&] { compact(occ, side); });
                if (cpu_path_)
                    ctx.pass(side ? "ssm_readback[back]" : "ssm_readback", [&] {
                        ssm::readMicroPatches(occluder_maps_[size_t(side)]->depth, map_size_, occ,
                                              side ? 0.0f : 1.0f, scratch_, patches_);
                        patches_buffer_.upload(std::span<const ssm::MicroPatch>(patches_),
                                               GL_SHADER_STORAGE_BUFFER, SSM_BINDING_PATCHES,
                                               sizeof(ssm::MicroPatch));
                    });
                ctx.pass(side ? "ssm_splat[back]" : "ssm_splat",
                         [&] { splat(light, occ, soft, side); });
            }
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
    }

    std::vector<DiagnosticChannel> diagnostics() const override {
        return {{"occlusion", DiagnosticChannel::Combine::Max},
                {"layer", DiagnosticChannel::Combine::Max}};
    }

private:
    // The farthest-receiver pyramid of each used receiver layer (receiver_max.comp), level by
    // level: a splat quad into layer k is culled where layer k has no receiver under it.
    void buildReceiverMax() {
        glUseProgram(max_program_.id());
        glBindTextureUnit(SSM_UNIT_RECEIVER_MAX_SOURCE, receiver_max_.id());
        glBindTextureUnit(SSM_UNIT_RECEIVER_MAX_LAYERS, receiver_layers_->depth.id());
        for (int layer = 0; layer < used_layers_; ++layer) {
            gl::setUniform(max_program_, "u_layer", layer);
            for (int level = 0; level < receiver_levels_; ++level) {
                const int size = std::max(ssm_size_ >> level, 1);
                glBindImageTexture(SSM_IMAGE_RECEIVER_MAX_TARGET, receiver_max_.id(), level,
                                   GL_FALSE, layer, GL_WRITE_ONLY, GL_R32F);
                gl::setUniform(max_program_, "u_from_depth", level == 0 ? 1 : 0);
                gl::setUniform(max_program_, "u_source_level", level - 1);
                const GLuint groups = static_cast<GLuint>((size + 7) / 8);
                glDispatchCompute(groups, groups, 1);
                glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
            }
        }
        glUseProgram(0);
    }

    // Appends side SIDE's non-empty occluder texels to its micro-patch list on the GPU and
    // makes their count the splat's instance count (no readback).
    void compact(const LightWindow& occ, int side) {
        const DrawCommand reset{4, 0, 0, 0};
        glNamedBufferSubData(command_.id(), 0, sizeof(reset), &reset);
        glUseProgram(compact_program_.id());
        glBindTextureUnit(SSM_UNIT_COMPACT_OCCLUDER, occluder_maps_[size_t(side)]->depth.id());
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, SSM_BINDING_PATCHES,
                         gpu_patches_[size_t(side)].id());
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, SSM_BINDING_COMMAND, command_.id());
        gl::setUniform(compact_program_, "u_empty", side ? 0.0f : 1.0f);
        gl::setUniform(compact_program_, "u_occ_near", occ.near);
        gl::setUniform(compact_program_, "u_occ_range", occ.far - occ.near);
        const GLuint groups = static_cast<GLuint>((map_size_ + 7) / 8);
        glDispatchCompute(groups, groups, 1);
        glMemoryBarrier(GL_COMMAND_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
        glUseProgram(0);
    }

    // Adds every micro-patch's occlusion of side SIDE into its soft shadow map.
    void splat(const scene::RectLight& light, const LightWindow& occ, const LightWindow& soft,
               int side) {
        const SoftShadowTarget& target = *soft_maps_[size_t(side)];
        const float zero[4] = {0, 0, 0, 0};
        for (const auto& fbo : target.fbos) glClearNamedFramebufferfv(fbo.id(), GL_COLOR, 0, zero);
        glViewport(0, 0, ssm_size_, ssm_size_);
        glDisable(GL_DEPTH_TEST);
        glDisable(GL_CULL_FACE);
        glEnable(GL_BLEND);
        glBlendEquation(GL_FUNC_ADD);
        glBlendFunc(GL_ONE, GL_ONE);
        const auto& p = splat_program_;
        glUseProgram(p.id());
        glBindTextureUnit(SSM_UNIT_SPLAT_RECEIVER, receiver_layers_->depth.id());
        if (clip_) glBindTextureUnit(SSM_UNIT_SPLAT_RECEIVER_MAX, receiver_max_.id());
        glBindTextureUnit(SSM_UNIT_SPLAT_OCC_IDS, occluder_maps_[size_t(side)]->ids.id());
        glBindTextureUnit(SSM_UNIT_SPLAT_LAYER_DEPTHS, receiver_layers_->depth.id());
        glBindTextureUnit(SSM_UNIT_SPLAT_LAYER_IDS, receiver_layers_->ids.id());
        gl::setUniform(p, "u_layer_count", layers_ == 1 ? 1 : std::max(used_layers_, 1));
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, SSM_BINDING_COUNTERS, counters_.id());
        gl::setUniform(p, "u_light_half", 0.5f * light.size);
        gl::setUniform(p, "u_ssm_lo", soft.lo);
        gl::setUniform(p, "u_ssm_size", soft.size);
        gl::setUniform(p, "u_ssm_texel", soft.size / static_cast<float>(ssm_size_));
        gl::setUniform(p, "u_receiver_far", soft.far);
        gl::setUniform(p, "u_receiver_near", soft.near);
        gl::setUniform(p, "u_receiver_range", soft.far - soft.near);
        gl::setParamUniforms(p, kSsmParams, params_);  // ssm_size, depth_bias, map_size
        gl::setUniform(p, "u_occ_lo", occ.lo);
        gl::setUniform(p, "u_occ_texel", occ.size / static_cast<float>(map_size_));
        glBindVertexArray(empty_vao_.id());
        if (!cpu_path_)
            glBindBufferBase(GL_SHADER_STORAGE_BUFFER, SSM_BINDING_PATCHES,
                             gpu_patches_[size_t(side)].id());
        // The same micro-patches into each receiver layer's soft shadow map (layered SSM).
        for (int layer = 0; layer < used_layers_; ++layer) {
            glBindFramebuffer(GL_FRAMEBUFFER, target.fbos[size_t(layer)].id());
            gl::setUniform(p, "u_layer", layer);
            if (cpu_path_) {
                // patches_buffer_ is bound at SSM_BINDING_PATCHES by the readback pass.
                if (!patches_.empty())
                    glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, GLsizei(patches_.size()));
            } else {
                glBindBuffer(GL_DRAW_INDIRECT_BUFFER, command_.id());
                glDrawArraysIndirect(GL_TRIANGLE_STRIP, nullptr);
                glBindBuffer(GL_DRAW_INDIRECT_BUFFER, 0);
            }
        }
        glBindVertexArray(0);
        glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
        glDisable(GL_BLEND);
        glUseProgram(0);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
    }

    // Projects the soft shadow map(s) onto the receivers: visibility and the occlusion channel.
    void visibility(frame::FrameContext& ctx, const scene::RectLight& light,
                    const LightWindow& soft, bool shadowed) {
        ctx.bindOutput();
        const float zero[4] = {0, 0, 0, 0};
        const float none[4] = {-1, 0, 0, 0};
        glClearBufferfv(GL_COLOR, 0, zero);
        glClearBufferfv(GL_COLOR, 1, zero);
        glClearBufferfv(GL_COLOR, 2, none);
        glDisable(GL_BLEND);
        glDisable(GL_DEPTH_TEST);
        const auto& p = visibility_program_;
        glUseProgram(p.id());
        glBindTextureUnit(SSM_UNIT_VISIBILITY_POSITION, ctx.gbuffer.position().id());
        glBindTextureUnit(SSM_UNIT_VISIBILITY_ID, ctx.gbuffer.id().id());
        glBindTextureUnit(SSM_UNIT_VISIBILITY_RECEIVES, receives_.id());
        glBindTextureUnit(SSM_UNIT_VISIBILITY_SSM, soft_maps_[0]->occlusion.id());
        if (two_sided_)
            glBindTextureUnit(SSM_UNIT_VISIBILITY_SSM_BACK, soft_maps_[1]->occlusion.id());
        glBindTextureUnit(SSM_UNIT_VISIBILITY_LAYERS, receiver_layers_->depth.id());
        ctx.gbuffer.bindGeometricNormal();
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, passes::kBindingCasterFlags,
                         ctx.gpu.casterFlags().id());
        passes::setLightFrameUniforms(p, light);
        gl::setUniform(p, "u_light_size", light.size);
        gl::setUniform(p, "u_layer_count", layers_ == 1 ? 1 : std::max(used_layers_, 1));
        gl::setUniform(p, "u_self_horizon", layers_ > 1 ? 1 : 0);
        gl::setUniform(p, "u_near", soft.near);
        gl::setUniform(p, "u_range", soft.far - soft.near);
        gl::setParamUniforms(p, kSsmParams, params_);  // depth_bias
        gl::setUniform(p, "u_ssm_lo", soft.lo);
        gl::setUniform(p, "u_ssm_size", soft.size);
        gl::setUniform(p, "u_shadowed", shadowed ? 1 : 0);
        fullscreen_.draw();
        glUseProgram(0);
    }

    Params params_;
    int map_size_, ssm_size_;
    bool fp16_, two_sided_, cpu_path_, clip_;
    float depth_bias_;  // also the peeling's gap (host)
    int layers_;
    int used_layers_ = 0;  // receiver layers holding a receiver this frame
    gl::Program peel_program_;
    gl::Program depth_program_, splat_program_, visibility_program_, max_program_, compact_program_;
    gl::Texture receiver_max_;
    int receiver_levels_ = 1;
    std::vector<std::unique_ptr<DepthTarget>> occluder_maps_;
    std::vector<std::unique_ptr<SoftShadowTarget>> soft_maps_;
    std::unique_ptr<ssm::ReceiverLayers> receiver_layers_;
    gl::Texture receives_;
    gl::Buffer counters_;
    gl::Buffer command_;                   // path=gpu: the splat's indirect draw
    std::vector<gl::Buffer> gpu_patches_;  // path=gpu: the micro-patch list of each side
    gl::VertexArray empty_vao_;
    gl::DynamicBuffer patches_buffer_{"ssm micro-patches"};
    std::vector<float> scratch_;
    std::vector<ssm::MicroPatch> patches_;
    passes::Fullscreen fullscreen_;
};

}  // namespace

const TechniqueInfo kSsmTechnique = {
    "ssm", "soft shadow maps (Atty et al. 2006): occluder micro-patches splatted as penumbra quads",
    kSsmParams,
    [](const Params& p) -> std::unique_ptr<Technique> { return std::make_unique<Ssm>(p); }};

}  // namespace penumbra::techniques
