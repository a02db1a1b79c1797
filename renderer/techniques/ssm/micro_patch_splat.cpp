// `ssm`'s micro-patch splat: the receivers' farthest-depth pyramids, the GPU compaction of the
// occluder map's texels into a micro-patch list, and the splat of every micro-patch's penumbra
// quad into the soft shadow map of each receiver layer (section 3; see ssm.h).
#include "glsl/techniques/ssm/bindings.glsl"
#include "renderer/gl/param_uniforms.h"
#include "renderer/techniques/ssm/ssm.h"

#include <algorithm>

namespace penumbra::techniques::ssm {

// The farthest-receiver pyramid of each used receiver layer (receiver_max.comp), level by
// level: a splat quad into layer k is culled where layer k has no receiver under it.
void Ssm::buildReceiverMax() {
    glUseProgram(max_program_.id());
    glBindTextureUnit(SSM_UNIT_RECEIVER_MAX_SOURCE, receiver_max_.id());
    glBindTextureUnit(SSM_UNIT_RECEIVER_MAX_LAYERS, receiver_layers_->depth.id());
    for (int layer = 0; layer < used_layers_; ++layer) {
        gl::setUniform(max_program_, "u_layer", layer);
        for (int level = 0; level < receiver_levels_; ++level) {
            const int size = std::max(ssm_size_ >> level, 1);
            glBindImageTexture(SSM_IMAGE_RECEIVER_MAX_TARGET, receiver_max_.id(), level, GL_FALSE,
                               layer, GL_WRITE_ONLY, GL_R32F);
            gl::setUniform(max_program_, "u_from_depth", level == 0 ? 1 : 0);
            gl::setUniform(max_program_, "u_source_level", level - 1);
            const GLuint groups = static_cast<GLuint>((size + 7) / 8);
            glDispatchCompute(groups, groups, 1);
            glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
        }
    }
    glUseProgram(0);
}

// Each used receiver layer's tangent plane per texel (receiver_planes.comp).
void Ssm::buildReceiverPlanes(const LightWindow& soft) {
    const auto& p = planes_program_;
    glUseProgram(p.id());
    glBindTextureUnit(SSM_UNIT_PLANES_LAYERS, receiver_layers_->depth.id());
    glBindImageTexture(SSM_IMAGE_PLANES_TARGET, receiver_planes_.id(), 0, GL_TRUE, 0, GL_WRITE_ONLY,
                       GL_RGBA16F);
    gl::setUniform(p, "u_ssm_lo", soft.lo);
    gl::setUniform(p, "u_ssm_texel", soft.size / static_cast<float>(ssm_size_));
    gl::setUniform(p, "u_receiver_near", soft.near);
    gl::setUniform(p, "u_receiver_range", soft.far - soft.near);
    const auto groups = static_cast<GLuint>((ssm_size_ + 7) / 8);
    glDispatchCompute(groups, groups, static_cast<GLuint>(std::max(used_layers_, 1)));
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
    glUseProgram(0);
}

// Lists side SIDE's non-empty occluder texels as its micro-patches on the GPU, in row-major
// order, and makes their count the splat's instance count (no readback): compact.comp's three
// phases over runs of consecutive texels (count per run, first slot per run, ordered writes).
void Ssm::compact(const LightWindow& occ, int side) {
    std::array<DrawCommand, ssm::kPatchClasses> reset{};
    for (auto& r : reset) r = {4, 0, 0, 0};
    glNamedBufferSubData(command_.id(), 0, sizeof(reset), reset.data());
    const auto& p = compact_program_;
    glUseProgram(p.id());
    glBindTextureUnit(SSM_UNIT_COMPACT_OCCLUDER, patchSource(side).id());
    if (lod_) glBindTextureUnit(SSM_UNIT_COMPACT_SLOPES, lod_slopes_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, SSM_BINDING_PATCHES,
                     gpu_patches_[size_t(side)].id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, SSM_BINDING_COMMAND, command_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, SSM_BINDING_RUNS, compact_runs_.id());
    gl::setUniform(p, "u_empty", emptyDepth(side));
    gl::setUniform(p, "u_merged", lod_ ? 1 : 0);
    gl::setUniform(p, "u_occ_near", occ.near);
    gl::setUniform(p, "u_occ_range", occ.far - occ.near);
    gl::setUniform(p, "u_run", compact_run_);
    gl::setUniform(p, "u_runs", compact_run_count_);
    const auto groups = static_cast<GLuint>((compact_run_count_ + 255) / 256);  // 256 per group
    for (int phase = 0; phase < 3; ++phase) {
        gl::setUniform(p, "u_phase", phase);
        glDispatchCompute(phase == 1 ? 1 : groups, 1, 1);
        glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    }
    glMemoryBarrier(GL_COMMAND_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
    glUseProgram(0);
}

void Ssm::clearSampleMasks() {
    const GLuint zero = 0;
    glClearTexSubImage(sample_masks_.id(), 0, 0, 0, 0, ssm_size_, ssm_size_,
                       used_layers_ * SSM_SAMPLE_WORDS, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
}

void Ssm::resolveSamples() {
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    const auto& p = resolve_program_;
    glUseProgram(p.id());
    glBindImageTexture(SSM_IMAGE_RESOLVE_MASKS, sample_masks_.id(), 0, GL_TRUE, 0, GL_READ_ONLY,
                       GL_R32UI);
    glBindImageTexture(SSM_IMAGE_RESOLVE_TARGET, soft_maps_[0]->occlusion.id(), 0, GL_TRUE, 0,
                       GL_WRITE_ONLY, fp16_ ? GL_R16F : GL_R32F);
    gl::setUniform(p, "u_size", ssm_size_);
    const auto groups = static_cast<GLuint>((ssm_size_ + 7) / 8);
    glDispatchCompute(groups, groups, static_cast<GLuint>(std::max(used_layers_, 1)));
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
    glUseProgram(0);
}

void Ssm::markDoneTexels(bool first) {
    const SoftShadowTarget& target = *soft_maps_[0];
    if (!first && !samples_) return;  // no receiver: as marked first
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glBindTextureUnit(SSM_UNIT_DONE_RECEIVER, receiver_layers_->depth.id());
    if (samples_)
        glBindImageTexture(SSM_IMAGE_DONE_MASKS, sample_masks_.id(), 0, GL_TRUE, 0, GL_READ_ONLY,
                           GL_R32UI);
    const auto draw = [&](const gl::Program& p) {
        glUseProgram(p.id());
        for (int layer = 0; layer < used_layers_; ++layer) {
            glBindFramebuffer(GL_FRAMEBUFFER, target.fbos[size_t(layer)].id());
            gl::setUniform(p, "u_layer", layer);
            fullscreen_.draw();
        }
    };
    if (first) {
        // Stencil 0 and each layer's receiver depths.
        const GLint zero = 0;
        for (int layer = 0; layer < used_layers_; ++layer)
            glClearNamedFramebufferiv(target.fbos[size_t(layer)].id(), GL_STENCIL, 0, &zero);
        glStencilFunc(GL_ALWAYS, 0, 0xff);
        glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_ALWAYS);
        glDepthMask(GL_TRUE);
        draw(fill_depth_program_);
        glDepthMask(GL_FALSE);
        glDisable(GL_DEPTH_TEST);
    }
    glStencilFunc(GL_ALWAYS, 1, 0xff);
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    draw(done_program_);
    glStencilFunc(GL_NOTEQUAL, 1, 0xff);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    if (!samples_) glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
}

// Adds every micro-patch's occlusion of side SIDE into its soft shadow map (accumulate=area),
// or its light samples into the texels' sample masks (accumulate=samples).
void Ssm::splat(const scene::RectLight& light, const LightWindow& occ, const LightWindow& soft,
                int side) {
    const SoftShadowTarget& target = *soft_maps_[samples_ ? 0 : size_t(side)];
    glViewport(0, 0, ssm_size_, ssm_size_);
    glDisable(GL_CULL_FACE);
    if (samples_) {
        glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    } else {
        const float zero[4] = {0, 0, 0, 0};
        for (const auto& fbo : target.fbos) glClearNamedFramebufferfv(fbo.id(), GL_COLOR, 0, zero);
        glEnable(GL_BLEND);
        glBlendEquation(GL_FUNC_ADD);
        glBlendFunc(GL_ONE, GL_ONE);
    }
    glEnable(GL_STENCIL_TEST);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, SSM_BINDING_COMMAND, command_.id());
    glBindBuffer(GL_DRAW_INDIRECT_BUFFER, command_.id());
    // patches_buffer_ is bound at SSM_BINDING_PATCHES by the CPU path's readback pass.
    if (!cpu_path_)
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, SSM_BINDING_PATCHES,
                         gpu_patches_[size_t(side)].id());
    glBindTextureUnit(SSM_UNIT_SPLAT_RECEIVER, receiver_layers_->depth.id());
    if (clip_) glBindTextureUnit(SSM_UNIT_SPLAT_RECEIVER_MAX, receiver_max_.id());
    glBindTextureUnit(SSM_UNIT_SPLAT_OCC_IDS, occluder_maps_[size_t(side)]->ids.id());
    glBindTextureUnit(SSM_UNIT_SPLAT_OCC_DEPTH, occluder_maps_[size_t(side)]->depth.id());
    glBindTextureUnit(SSM_UNIT_SPLAT_LAYER_IDS, receiver_layers_->ids.id());
    glBindTextureUnit(SSM_UNIT_SPLAT_PLANES, receiver_planes_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, SSM_BINDING_COUNTERS, counters_.id());
    // Texels with nothing left to add are skipped before the splat's shader runs: no receiver,
    // or every sample hidden by the sides before (marks between the classes of a side gained
    // nothing measurable: rand3001 front 944 -> 948 ms at 320x240).
    markDoneTexels(side == 0);
    glEnable(GL_DEPTH_TEST);  // each quad at the receiver depth it needs to be behind it
    glDepthFunc(GL_LESS);
    glDepthMask(GL_FALSE);
    if (samples_)
        glBindImageTexture(SSM_IMAGE_SPLAT_MASKS, sample_masks_.id(), 0, GL_TRUE, 0, GL_READ_WRITE,
                           GL_R32UI);
    glBindVertexArray(empty_vao_.id());
    // Each patch class by its own program from its own range of the list (compact.comp or the
    // readback), the same micro-patches into each receiver layer's soft shadow map (layered SSM).
    for (int c = 0; c < ssm::kPatchClasses; ++c) {
        const auto& p = splat_programs_[size_t(c)];
        glUseProgram(p.id());
        gl::setUniform(p, "u_occ_near", occ.near);
        gl::setUniform(p, "u_occ_range", occ.far - occ.near);
        gl::setUniform(p, "u_far_side", side > 0 ? 1 : 0);
        gl::setUniform(p, "u_far_empty", emptyDepth(side));
        gl::setUniform(p, "u_layered", layers_ > 1 ? 1 : 0);
        gl::setUniform(p, "u_light_half", 0.5f * light.size);
        gl::setUniform(p, "u_ssm_lo", soft.lo);
        gl::setUniform(p, "u_ssm_size", soft.size);
        gl::setUniform(p, "u_ssm_texel", soft.size / static_cast<float>(ssm_size_));
        gl::setUniform(p, "u_receiver_far", soft.far);
        gl::setUniform(p, "u_receiver_near", soft.near);
        gl::setUniform(p, "u_receiver_range", soft.far - soft.near);
        gl::setParamUniforms(p, kSsmParams, params_);      // ssm_size, depth_bias, map_size, seal
        if (!samples_) gl::setUniform(p, "u_seal", 0.0f);  // the paper's sum counts overlaps twice
        gl::setUniform(p, "u_occ_lo", occ.lo);
        gl::setUniform(p, "u_occ_texel", occ.size / static_cast<float>(map_size_));
        for (int layer = 0; layer < used_layers_; ++layer) {
            glBindFramebuffer(GL_FRAMEBUFFER, target.fbos[size_t(layer)].id());
            gl::setUniform(p, "u_layer", layer);
            glDrawArraysIndirect(GL_TRIANGLE_STRIP,
                                 reinterpret_cast<const void*>(sizeof(DrawCommand) * size_t(c)));
        }
    }
    glBindBuffer(GL_DRAW_INDIRECT_BUFFER, 0);
    glBindVertexArray(0);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_DEPTH_TEST);
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glUseProgram(0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

}  // namespace penumbra::techniques::ssm
