// `bitmask`'s per-pixel passes over the search areas (search.glsl): classify (search area,
// level of the budget), the bilateral smoothing of the fractional level (4.2) and the
// visibility by back-projection, and the statistics of Table 2 (see bitmask.h).
#include "glsl/techniques/bitmask/bindings.glsl"
#include "renderer/gl/param_uniforms.h"
#include "renderer/passes/cover_depth.h"
#include "renderer/passes/light_depth.h"
#include "renderer/techniques/bitmask/bitmask.h"
#include "renderer/techniques/bitmask/mask_textures.h"

#include <algorithm>
#include <cmath>

namespace penumbra::techniques::bitmask {

// The uniforms and textures of search.glsl.
void Bitmask::bindSearch(const frame::FrameContext& ctx, const gl::Program& p,
                         const scene::RectLight& light, const passes::LightWindow& window) {
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

void Bitmask::classify(frame::FrameContext& ctx, const scene::RectLight& light,
                       const passes::LightWindow& window, bool shadowed) {
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
void Bitmask::smoothLoq(frame::FrameContext& ctx) {
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

// Two draws (passes::drawCovered): the cover program writes the lit and umbra pixels and
// discards the penumbra; the back-projecting program runs on the penumbra only.
// The same image as one program for all: on llvmpipe, which runs a shader's every branch for
// every fragment, the back-projection's code no longer runs for the pixels that skip it.
void Bitmask::visibility(frame::FrameContext& ctx, const scene::RectLight& light,
                         const passes::LightWindow& window) {
    const GLuint output = ctx.bindOutput();
    cover_depth_.attach(output, ctx.gbuffer.width(), ctx.gbuffer.height());
    glDisable(GL_BLEND);
    glDisable(GL_DEPTH_TEST);
    auto draw = [&](const gl::Program& p) {
        glUseProgram(p.id());
        bindSearch(ctx, p, light, window);
        if (use_bitmask_) {
            glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BITMASK_BINDING_VISIBILITY_MASKS,
                             masks_.id());
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
        if (far_layer_) glBindTextureUnit(BITMASK_UNIT_VISIBILITY_FAR, ranges_->farLayer().id());
        if (own_ids_ && !gap_fill_) {  // with gap filling the neighbour depths carry them
            glBindTextureUnit(BITMASK_UNIT_VISIBILITY_OWNERS, ranges_->hsmOwners().id());
            if (far_layer_)
                glBindTextureUnit(BITMASK_UNIT_VISIBILITY_FAR_OWNERS, ranges_->farOwners().id());
        }
        if (neighbours_)
            glBindTextureUnit(BITMASK_UNIT_VISIBILITY_NEIGHBOURS, neighbours_->texture().id());
        if (far_neighbours_)
            glBindTextureUnit(BITMASK_UNIT_VISIBILITY_FAR_NEIGHBOURS,
                              far_neighbours_->texture().id());
        if (far_rects_) {
            glBindTextureUnit(BITMASK_UNIT_VISIBILITY_FAR_RECT_EXTENT, far_rects_->extent().id());
            glBindTextureUnit(BITMASK_UNIT_VISIBILITY_FAR_RECT_DEPTH, far_rects_->depth().id());
        }
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BITMASK_BINDING_VISIBILITY_STATS, stats_.id());
        fullscreen_.draw();
    };
    passes::drawCovered([&] { draw(visibility_cover_); }, [&] { draw(visibility_); });
    passes::CoverDepth::detach(output);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    glUseProgram(0);
}

// Table 2 of the paper: share of pixels that back-project, mean and standard deviation of
// the micro-occluders each of them back-projects (sums kept over lights).
void Bitmask::addStatistics(frame::FrameContext& ctx, int width, int height) {
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

}  // namespace penumbra::techniques::bitmask
