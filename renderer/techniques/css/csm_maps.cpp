// The prefiltered maps of `css`: see csm_maps.h.
#include "renderer/techniques/css/csm_maps.h"
#include "glsl/techniques/css/bindings.glsl"

#include <algorithm>
#include <bit>
#include <string>

#include "renderer/core/error.h"

namespace penumbra::techniques::css {

float depthMargin(int order, float shift) {
    return std::min(shift + 0.5f / static_cast<float>(order), 0.3f);
}

namespace {
constexpr float kMinGapShare = 0.25f;
}  // namespace

passes::LightWindow mapWindow(const scene::RectLight& light, passes::Boxes casters,
                              passes::Boxes scene, float margin) {
    passes::LightWindow w = passes::windowOf(light, casters);
    if (w.empty()) return w;
    // The receivers' gap past the farthest caster: the share MARGIN of the normalised range, so
    // that a receiver clamped to 1 - MARGIN lies MARGIN behind that caster, as one just behind
    // it would; and at least a quarter of the casters' far distance. The ring shift and the
    // series' ramp are fixed shares of the range, and what they must clear (a surface's own
    // depth under a kernel, which spreads with its distance from the light) grows with that
    // distance, not with the casters' extent: with the gap alone (1 % of the distance at
    // least) bar_grid's bars shadowed themselves (receivers' error 0.0116 -> 0.0224 at
    // 320 x 240); a quarter keeps them (0.0127; 0.15-0.35 read within 0.002 on the scenes
    // that moved, scripts/conformance).
    const float gap =
        std::max(margin * (w.far - w.near) / (1.0f - 3.0f * margin), kMinGapShare * w.far);
    w.far = std::max(w.far, std::min(passes::windowOf(light, scene).far, w.far + gap));
    return w;
}

DepthRange depthRange(const passes::LightWindow& w, float m) {
    const float pad = m * (w.far - w.near) / (1.0f - 2.0f * m);
    return {w.near - pad, w.far + pad, 1.0f - m};
}

CsmMaps::CsmMaps(int map_size, int order, bool mipmap, bool sat, float middle_at)
    : map_size_(map_size),
      layers_(basisLayers(order)),
      depth_pass_("css depth", middle_at > 0.0f ? passes::LightDepthPass::Output::Range
                                                : passes::LightDepthPass::Output::Depth),
      middle_at_(middle_at) {
    const gl::Defines defines = {{"ORDER", std::to_string(order)},
                                 {"MIDDLE", middle_at > 0.0f ? "1" : "0"}};
    if (mipmap)
        basis_program_ = gl::buildProgram("css basis", {"techniques/css/basis.comp"}, defines);
    if (sat) {
        gl::Defines rows = defines;
        rows.emplace_back("SAT_ROWS", "1");
        sat_rows_program_ =
            gl::buildProgram("css basis row sums", {"techniques/css/basis.comp"}, rows);
    }
    if (middle_at > 0.0f)
        range_ = std::make_unique<passes::LightDepthRangeTarget>(map_size, "css shadow maps");
    else
        depth_ = std::make_unique<passes::LightDepthTarget>(map_size, "css shadow map");
    // Centred values are 0 for empty texels, so outside the map is the zero border colour.
    const float border[4] = {0, 0, 0, 0};
    if (mipmap) {
        const int levels = std::bit_width(static_cast<unsigned>(map_size));
        basis_ = gl::createTexture(GL_TEXTURE_2D_ARRAY, "css basis images");
        glTextureStorage3D(basis_.id(), levels, GL_RGBA32F, map_size, map_size, layers_);
        glTextureParameteri(basis_.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
        glTextureParameteri(basis_.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glTextureParameteri(basis_.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
        glTextureParameteri(basis_.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_BORDER);
        glTextureParameterfv(basis_.id(), GL_TEXTURE_BORDER_COLOR, border);
    }
    search_sampler_ = gl::createSampler("css search sampler");
    glSamplerParameteri(search_sampler_.id(), GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_NEAREST);
    glSamplerParameteri(search_sampler_.id(), GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glSamplerParameteri(search_sampler_.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
    glSamplerParameteri(search_sampler_.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_BORDER);
    glSamplerParameterfv(search_sampler_.id(), GL_TEXTURE_BORDER_COLOR, border);
    if (sat) sat_ = std::make_unique<passes::SummedAreaTable>(map_size, layers_, "css basis SAT");
}

void CsmMaps::renderDepth(const passes::GpuScene& scene, const scene::RectLight& light,
                          const passes::LightWindow& w, const DepthRange& range) {
    const passes::LightDepthView view{w.viewProj(light), range.near,
                                      1.0f / (range.far - range.near)};
    if (range_)
        range_->render(scene, depth_pass_, passes::GpuScene::Filter::Casters, light, view);
    else
        depth_->render(scene, depth_pass_, passes::GpuScene::Filter::Casters, light, view, false);
}

void CsmMaps::buildBasis(Filter filter) {
    const bool sat = filter == Filter::Sat;
    if (sat && !sat_) throw RuntimeError("css: summed-area tables were not prepared");
    if (!sat && !basis_program_) throw RuntimeError("css: mipmaps were not prepared");
    const gl::Program& program = sat ? sat_rows_program_ : basis_program_;
    glUseProgram(program.id());
    if (range_) {
        gl::setUniform(program, "u_middle_at", middle_at_);
        glBindTextureUnit(CSS_UNIT_BASIS_DEPTH, range_->nearest.id());
        glBindTextureUnit(CSS_UNIT_BASIS_FAR, range_->farthest.id());
    } else {
        glBindTextureUnit(CSS_UNIT_BASIS_DEPTH, depth_->depth.id());
    }
    glBindImageTexture(CSS_IMAGE_BASIS, sat ? sat_->table().id() : basis_.id(), 0, GL_TRUE, 0,
                       GL_WRITE_ONLY, GL_RGBA32F);
    if (sat) {  // an invocation per row
        glDispatchCompute(static_cast<GLuint>((map_size_ + 63) / 64), 1, 1);
    } else {
        const GLuint groups = static_cast<GLuint>((map_size_ + 7) / 8);
        glDispatchCompute(groups, groups, 1);
    }
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT |
                    GL_TEXTURE_UPDATE_BARRIER_BIT);
    glUseProgram(0);
}

void CsmMaps::prefilter(Filter filter) {
    if (filter == Filter::Mipmap) {
        if (!basis_) throw RuntimeError("css: mipmaps were not prepared");
        glGenerateTextureMipmap(basis_.id());
        return;
    }
    if (!sat_) throw RuntimeError("css: summed-area tables were not prepared");
    sat_->sumColumns();
}

const gl::Texture& CsmMaps::filtered(Filter filter) const {
    if (filter == Filter::Sat) {
        if (!sat_) throw RuntimeError("css: summed-area tables were not prepared");
        return sat_->table();
    }
    return basis_;
}

}  // namespace penumbra::techniques::css
