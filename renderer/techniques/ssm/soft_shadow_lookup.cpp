// `ssm`'s soft-shadow-map lookup: each receiver's visibility from the soft shadow map(s) of
// its receiver layer, and the occlusion and layer diagnostics (see ssm.h).
#include "glsl/techniques/ssm/bindings.glsl"
#include "renderer/gl/param_uniforms.h"
#include "renderer/passes/bindings.h"
#include "renderer/techniques/ssm/ssm.h"

#include <algorithm>

namespace penumbra::techniques::ssm {

// Projects the soft shadow map(s) onto the receivers: visibility and the occlusion channel. Two
// programs in turn (passes::drawCovered): the cover writes the pixels that no texel around them
// shadows, and the full program takes the rest (the same image as the full program alone: on
// llvmpipe its layer matching costs every pixel its whole code otherwise).
void Ssm::visibility(frame::FrameContext& ctx, const scene::RectLight& light,
                     const LightWindow& soft, bool shadowed) {
    const GLuint output = ctx.bindOutput();
    const float zero[4] = {0, 0, 0, 0};
    const float none[4] = {-1, 0, 0, 0};
    glClearBufferfv(GL_COLOR, 0, zero);
    glClearBufferfv(GL_COLOR, 1, zero);
    glClearBufferfv(GL_COLOR, 2, none);
    glDisable(GL_BLEND);
    glDisable(GL_DEPTH_TEST);
    visibility_cover_depth_.attach(output, ctx.gbuffer.width(), ctx.gbuffer.height());
    auto draw = [&](const gl::Program& p) {
        glUseProgram(p.id());
        glBindTextureUnit(SSM_UNIT_VISIBILITY_POSITION, ctx.gbuffer.position().id());
        glBindTextureUnit(SSM_UNIT_VISIBILITY_ID, ctx.gbuffer.id().id());
        glBindTextureUnit(SSM_UNIT_VISIBILITY_RECEIVES, receives_.id());
        glBindTextureUnit(SSM_UNIT_VISIBILITY_SSM, soft_maps_[0]->occlusion.id());
        if (softMapCount() == 2)
            glBindTextureUnit(SSM_UNIT_VISIBILITY_SSM_BACK, soft_maps_[1]->occlusion.id());
        glBindTextureUnit(SSM_UNIT_VISIBILITY_LAYERS, receiver_layers_->depth.id());
        glBindTextureUnit(SSM_UNIT_VISIBILITY_LAYER_IDS, receiver_layers_->ids.id());
        ctx.gbuffer.bindGeometricNormal();
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, passes::kBindingCasterFlags,
                         ctx.gpu.casterFlags().id());
        passes::setLightFrameUniforms(p, light);
        gl::setUniform(p, "u_light_size", light.size);
        gl::setUniform(p, "u_layer_count", layers_ == 1 ? 1 : std::max(used_layers_, 1));
        gl::setUniform(p, "u_layered", layers_ > 1 ? 1 : 0);
        gl::setUniform(p, "u_near", soft.near);
        gl::setUniform(p, "u_range", soft.far - soft.near);
        gl::setParamUniforms(p, kSsmParams, params_);  // depth_bias
        gl::setUniform(p, "u_ssm_lo", soft.lo);
        gl::setUniform(p, "u_ssm_size", soft.size);
        gl::setUniform(p, "u_shadowed", shadowed ? 1 : 0);
        fullscreen_.draw();
    };
    passes::drawCovered([&] { draw(visibility_cover_); }, [&] { draw(visibility_program_); });
    passes::CoverDepth::detach(output);
    glUseProgram(0);
}

}  // namespace penumbra::techniques::ssm
