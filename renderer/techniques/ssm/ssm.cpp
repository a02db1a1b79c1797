// `ssm`: soft shadow maps (Atty et al. 2006). Occluder micro-patches from a light-centred depth
// map are splatted as penumbra quads into a soft shadow map that the receivers look up.
#include <algorithm>
#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "renderer/core/error.h"
#include "renderer/gl/dynamic_buffer.h"
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

constexpr std::array kSsmParams = {
    intParam("map_size", 256, 16, 4096, "occluder map width and height in texels"),
    intParam("ssm_size", 256, 16, 4096, "soft shadow map (and receiver map) width and height"),
    enumParam("precision", "fp32", "fp32|fp16",
              "soft-shadow-map blending precision (fp16 reproduces the paper's Appendix A)"),
    boolParam("two_sided", false,
              "also splat the farthest (back) occluder surfaces into a second map, merged by max"),
    enumParam("path", "gpu", "gpu|cpu",
              "gpu: micro-patch list compacted on the GPU, drawn indirect; cpu: read back (4.1)"),
    boolParam("clip", true,
              "fit each penumbra quad to the farthest receiver under it, and cull it when none"),
    floatParam("depth_bias", 0.002, 0.0, 0.5,
               "a micro-patch shadows a receiver only when nearer by this fraction of its depth"),
};

constexpr unsigned kBindingCounters = 3;  // splat.vert's Counters
constexpr unsigned kBindingPatches = 4;   // splat.vert's and compact.comp's Patches
constexpr unsigned kBindingCommand = 5;   // compact.comp's Command (path=gpu)

// glDrawArraysIndirect's command: 4 strip vertices, instances = micro-patches.
struct DrawCommand {
    std::uint32_t vertices, instances, first, base_instance;
};

class Ssm final : public Technique {
public:
    explicit Ssm(const Params& p)
        : map_size_(p.getInt("map_size")),
          ssm_size_(p.getInt("ssm_size")),
          fp16_(p.getString("precision") == "fp16"),
          two_sided_(p.getBool("two_sided")),
          cpu_path_(p.getString("path") == "cpu"),
          clip_(p.getBool("clip")),
          depth_bias_(static_cast<float>(p.getFloat("depth_bias"))) {}

    void prepare(const gl::ContextInfo&, const passes::GpuScene& scene) override {
        bool occluders = false, receivers = false;
        std::vector<std::uint8_t> receives;
        for (const auto& o : scene.objects()) {
            occluders |= scene::castsShadow(o.shadow);
            receivers |= scene::receivesShadow(o.shadow);
            if (static_cast<size_t>(o.id) >= receives.size())
                receives.resize(static_cast<size_t>(o.id) + 1, 0);
            receives[static_cast<size_t>(o.id)] = scene::receivesShadow(o.shadow) ? 255 : 0;
        }
        if (!occluders)
            throw InputError(
                "technique ssm: no occluders: give some object shadow \"occluder\" or \"both\"");
        if (!receivers)
            throw InputError(
                "technique ssm: no receivers: give some object shadow \"receiver\" or \"both\"");
        receives_ = gl::createTexture2D(GL_R8, static_cast<int>(receives.size()), 1,
                                        "ssm receiving objects");
        glTextureSubImage2D(receives_.id(), 0, 0, 0, static_cast<int>(receives.size()), 1, GL_RED,
                            GL_UNSIGNED_BYTE, receives.data());

        depth_program_ = gl::buildProgram(
            "ssm depth", {"techniques/ssm/depth.vert", "techniques/ssm/depth.frag"});
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
                map_size_, side ? "ssm occluder map (back)" : "ssm occluder map"));
            soft_maps_.push_back(std::make_unique<SoftShadowTarget>(
                ssm_size_, format, side ? "ssm soft shadow map (back)" : "ssm soft shadow map"));
        }
        receiver_map_ = std::make_unique<DepthTarget>(ssm_size_, "ssm receiver map");
        if (clip_) {
            max_program_ =
                gl::buildProgram("ssm receiver max", {"techniques/ssm/receiver_max.comp"});
            receiver_levels_ = 1;
            while ((ssm_size_ >> receiver_levels_) > 0) ++receiver_levels_;
            receiver_max_ = gl::createTexture(GL_TEXTURE_2D, "ssm receiver max pyramid");
            glTextureStorage2D(receiver_max_.id(), receiver_levels_, GL_R32F, ssm_size_, ssm_size_);
            glTextureParameteri(receiver_max_.id(), GL_TEXTURE_MIN_FILTER,
                                GL_NEAREST_MIPMAP_NEAREST);
            glTextureParameteri(receiver_max_.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        }
        counters_ = gl::createBuffer("ssm counters");
        glNamedBufferStorage(counters_.id(), 2 * sizeof(std::uint32_t), nullptr,
                             GL_DYNAMIC_STORAGE_BIT);
        empty_vao_ = gl::createVertexArray("ssm splat");
    }

    void render(render::FrameContext& ctx) override {
        const scene::RectLight& light = ctx.currentLight();
        passes::Bounds receiver_bounds;
        for (const auto& o : ctx.gpu.objects())
            if (scene::receivesShadow(o.shadow)) receiver_bounds.extend(o.world_bounds);
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
                receiver_map_->render(ctx.gpu, depth_program_, passes::GpuScene::Filter::Receivers,
                                      soft.viewProj(light), light, soft.near,
                                      1.0f / (soft.far - soft.near), false);
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
                                               GL_SHADER_STORAGE_BUFFER, kBindingPatches,
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
    }

    std::vector<DiagnosticChannel> diagnostics() const override {
        return {{"occlusion", DiagnosticChannel::Combine::Max}};
    }

private:
    // The farthest-receiver pyramid of the receiver map (receiver_max.comp), level by level.
    void buildReceiverMax() {
        glUseProgram(max_program_.id());
        for (int level = 0; level < receiver_levels_; ++level) {
            const int size = std::max(ssm_size_ >> level, 1);
            glBindTextureUnit(0, level == 0 ? receiver_map_->depth.id() : receiver_max_.id());
            glBindImageTexture(0, receiver_max_.id(), level, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
            gl::setUniform(max_program_, "u_from_depth", level == 0 ? 1 : 0);
            gl::setUniform(max_program_, "u_source_level", level - 1);
            const GLuint groups = static_cast<GLuint>((size + 7) / 8);
            glDispatchCompute(groups, groups, 1);
            glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
        }
        glUseProgram(0);
    }

    // Appends side SIDE's non-empty occluder texels to its micro-patch list on the GPU and
    // makes their count the splat's instance count (no readback).
    void compact(const LightWindow& occ, int side) {
        const DrawCommand reset{4, 0, 0, 0};
        glNamedBufferSubData(command_.id(), 0, sizeof(reset), &reset);
        glUseProgram(compact_program_.id());
        glBindTextureUnit(0, occluder_maps_[size_t(side)]->depth.id());
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kBindingPatches,
                         gpu_patches_[size_t(side)].id());
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kBindingCommand, command_.id());
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
        glBindFramebuffer(GL_FRAMEBUFFER, target.fbo.id());
        glViewport(0, 0, ssm_size_, ssm_size_);
        const float zero[4] = {0, 0, 0, 0};
        glClearNamedFramebufferfv(target.fbo.id(), GL_COLOR, 0, zero);
        glDisable(GL_DEPTH_TEST);
        glDisable(GL_CULL_FACE);
        glEnable(GL_BLEND);
        glBlendEquation(GL_FUNC_ADD);
        glBlendFunc(GL_ONE, GL_ONE);
        const auto& p = splat_program_;
        glUseProgram(p.id());
        glBindTextureUnit(1, receiver_map_->depth.id());
        if (clip_) glBindTextureUnit(2, receiver_max_.id());
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kBindingCounters, counters_.id());
        gl::setUniform(p, "u_light_half", 0.5f * light.size);
        gl::setUniform(p, "u_ssm_lo", soft.lo);
        gl::setUniform(p, "u_ssm_size", soft.size);
        gl::setUniform(p, "u_ssm_res", ssm_size_);
        gl::setUniform(p, "u_ssm_texel", soft.size / static_cast<float>(ssm_size_));
        gl::setUniform(p, "u_receiver_far", soft.far);
        gl::setUniform(p, "u_receiver_near", soft.near);
        gl::setUniform(p, "u_receiver_range", soft.far - soft.near);
        gl::setUniform(p, "u_depth_bias", depth_bias_);
        gl::setUniform(p, "u_map_size", map_size_);
        gl::setUniform(p, "u_occ_lo", occ.lo);
        gl::setUniform(p, "u_occ_texel", occ.size / static_cast<float>(map_size_));
        glBindVertexArray(empty_vao_.id());
        if (cpu_path_) {
            // patches_buffer_ is bound at kBindingPatches by the readback pass.
            if (!patches_.empty())
                glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, GLsizei(patches_.size()));
        } else {
            glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kBindingPatches,
                             gpu_patches_[size_t(side)].id());
            glBindBuffer(GL_DRAW_INDIRECT_BUFFER, command_.id());
            glDrawArraysIndirect(GL_TRIANGLE_STRIP, nullptr);
            glBindBuffer(GL_DRAW_INDIRECT_BUFFER, 0);
        }
        glBindVertexArray(0);
        glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
        glDisable(GL_BLEND);
        glUseProgram(0);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
    }

    // Projects the soft shadow map(s) onto the receivers: visibility and the occlusion channel.
    void visibility(render::FrameContext& ctx, const scene::RectLight& light,
                    const LightWindow& soft, bool shadowed) {
        ctx.bindOutput();
        const float zero[4] = {0, 0, 0, 0};
        glClearBufferfv(GL_COLOR, 0, zero);
        glClearBufferfv(GL_COLOR, 1, zero);
        glDisable(GL_BLEND);
        glDisable(GL_DEPTH_TEST);
        const auto& p = visibility_program_;
        glUseProgram(p.id());
        glBindTextureUnit(0, ctx.gbuffer.position().id());
        glBindTextureUnit(1, ctx.gbuffer.id().id());
        glBindTextureUnit(2, receives_.id());
        glBindTextureUnit(3, soft_maps_[0]->occlusion.id());
        if (two_sided_) glBindTextureUnit(4, soft_maps_[1]->occlusion.id());
        passes::setLightFrameUniforms(p, light);
        gl::setUniform(p, "u_ssm_lo", soft.lo);
        gl::setUniform(p, "u_ssm_size", soft.size);
        gl::setUniform(p, "u_shadowed", shadowed ? 1 : 0);
        fullscreen_.draw();
        glUseProgram(0);
    }

    int map_size_, ssm_size_;
    bool fp16_, two_sided_, cpu_path_, clip_;
    float depth_bias_;
    gl::Program depth_program_, splat_program_, visibility_program_, max_program_, compact_program_;
    gl::Texture receiver_max_;
    int receiver_levels_ = 1;
    std::vector<std::unique_ptr<DepthTarget>> occluder_maps_;
    std::vector<std::unique_ptr<SoftShadowTarget>> soft_maps_;
    std::unique_ptr<DepthTarget> receiver_map_;
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
