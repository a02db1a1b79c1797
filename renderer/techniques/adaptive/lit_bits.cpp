// `adaptive`: per-pixel shadow bits of every map of a light, set batch by batch and read back or
// weighted into visibility; see lit_bits.h.
#include "renderer/techniques/adaptive/lit_bits.h"
#include "glsl/techniques/adaptive/bindings.glsl"

#include <algorithm>
#include <vector>

#include "renderer/passes/bindings.h"
#include "renderer/passes/cover_depth.h"
#include "renderer/passes/light_depth.h"

namespace penumbra::techniques::adaptive {

LitBits::LitBits()
    : test_program_(gl::buildProgram(
          "adaptive lit bits", {"passes/fullscreen.vert", "techniques/adaptive/lit_bits.frag"})),
      tile_test_program_(gl::buildProgram(
          "adaptive lit bits in tiles",
          {"techniques/adaptive/tile_quads.vert", "techniques/adaptive/lit_bits.frag"})),
      eval_program_(
          gl::buildProgram("adaptive lit evaluation",
                           {"passes/fullscreen.vert", "techniques/adaptive/lit_eval.frag"})),
      settle_program_(gl::buildProgram(
          "adaptive lit evaluation of the lit pixels",
          {"passes/fullscreen.vert", "techniques/adaptive/lit_eval.frag"}, {{"SETTLE", "1"}})),
      region_program_(
          gl::buildProgram("adaptive lit region",
                           {"passes/fullscreen.vert", "techniques/adaptive/lit_region.frag"})),
      horizon_program_(
          gl::buildProgram("adaptive horizon tiles",
                           {"passes/fullscreen.vert", "techniques/adaptive/horizon_tiles.frag"})) {
    sampler_ = createRawDepthSampler();
}

LitBits::~LitBits() {
    glDeleteSamplers(1, &sampler_);
}

void LitBits::begin(const passes::GBuffer& gbuffer, int views) {
    if (gbuffer.width() != width_ || gbuffer.height() != height_ || !fbo_.id()) {
        width_ = gbuffer.width();
        height_ = gbuffer.height();
        fbo_ = gl::createFramebuffer("adaptive lit bits");
        stencil_ = gl::createTexture2D(GL_STENCIL_INDEX8, width_, height_, "adaptive lit stencil");
        glNamedFramebufferTexture(fbo_.id(), GL_STENCIL_ATTACHMENT, stencil_.id(), 0);
        passes::checkFramebuffer(fbo_, "adaptive lit bits");
    }
    const GLint all = 1;
    glClearNamedFramebufferiv(fbo_.id(), GL_STENCIL, 0, &all);
    region_marked_ = false;
    planes_ = std::max(1, (views + 31) / 32);
    const size_t need = size_t(planes_) * size_t(width_) * size_t(height_);
    if (need > capacity_ || !bits_.id()) {
        bits_ = gl::createBuffer("adaptive lit bits");
        glNamedBufferData(bits_.id(), GLsizeiptr(need * sizeof(GLuint)), nullptr, GL_DYNAMIC_READ);
        capacity_ = need;
    }
    const GLuint zero = 0;
    glClearNamedBufferSubData(bits_.id(), GL_R32UI, 0, GLsizeiptr(need * sizeof(GLuint)),
                              GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
}

void LitBits::markLitRegion(const passes::GBuffer& gbuffer, const scene::RectLight& light,
                            const CompareSettings& s, float texel_size, const LitRegion& region) {
    const GLint none = 0;
    glClearNamedFramebufferiv(fbo_.id(), GL_STENCIL, 0, &none);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
    glViewport(0, 0, width_, height_);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_ALWAYS, 1, 0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    const gl::Program& p = region_program_;
    glUseProgram(p.id());
    bindReceiverTest(p, gbuffer, s);
    glBindTextureUnit(ADAPTIVE_UNIT_LIT_REGION, region.pyramid);
    gl::setUniform(p, "u_texel_size", texel_size);
    gl::setUniform(p, "u_region_size", region.size);
    gl::setUniform(p, "u_region_levels", region.levels);
    gl::setUniform(p, "u_win_lo", region.window.lo);
    gl::setUniform(p, "u_texel", region.window.size / static_cast<float>(region.size));
    gl::setUniform(p, "u_near", region.window.near);
    gl::setUniform(p, "u_light_half", 0.5f * light.size);
    passes::setLightFrameUniforms(p, light);
    if (!marked_) marked_ = gl::createQuery(GL_SAMPLES_PASSED, "adaptive lit region pixels");
    glBeginQuery(GL_SAMPLES_PASSED, marked_.id());
    fullscreen_.draw();
    glEndQuery(GL_SAMPLES_PASSED);
    glDisable(GL_STENCIL_TEST);
    glUseProgram(0);
    region_marked_ = true;
}

std::optional<double> LitBits::markedPixels() const {
    if (!region_marked_) return std::nullopt;
    GLuint64 n = 0;
    glGetQueryObjectui64v(marked_.id(), GL_QUERY_RESULT, &n);
    return static_cast<double>(n);
}

TileMask LitBits::horizonTiles(const passes::GBuffer& gbuffer, const scene::RectLight& light,
                               const gl::Buffer& caster_flags, const ScreenTiles& tiles) {
    std::vector<GLuint> flags(size_t(tiles.count()), 0u);  // cleared, and bound
    horizon_tiles_.upload(std::span<const GLuint>(flags), GL_SHADER_STORAGE_BUFFER,
                          ADAPTIVE_BINDING_LIT_HORIZON_TILES);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());  // a stencil only, untouched: no test
    glViewport(0, 0, width_, height_);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glDisable(GL_STENCIL_TEST);
    const gl::Program& p = horizon_program_;
    glUseProgram(p.id());
    glBindTextureUnit(ADAPTIVE_UNIT_COMPARE_POSITION, gbuffer.position().id());
    glBindTextureUnit(ADAPTIVE_UNIT_COMPARE_ID, gbuffer.id().id());
    gbuffer.bindGeometricNormal();
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, passes::kBindingCasterFlags, caster_flags.id());
    gl::setUniform(p, "u_tile_side", tiles.side());
    gl::setUniform(p, "u_tile_columns", tiles.columns());
    gl::setUniform(p, "u_light_half", 0.5f * light.size);
    passes::setLightFrameUniforms(p, light);
    fullscreen_.draw();
    glUseProgram(0);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    glGetNamedBufferSubData(horizon_tiles_.id(), 0, GLsizeiptr(flags.size() * sizeof(GLuint)),
                            flags.data());
    TileMask out(flags.size());
    for (size_t t = 0; t < flags.size(); ++t) out[t] = flags[t] != 0u;
    return out;
}

void LitBits::setTestedTiles(const ScreenTiles& tiles, std::span<const TileMask> view_tiles) {
    std::vector<GLuint> words(size_t(tiles.count()) * size_t(planes_), 0u);
    for (size_t k = 0; k < view_tiles.size() && k < size_t(32 * planes_); ++k)
        for (size_t t = 0; t < size_t(tiles.count()); ++t)
            if (view_tiles[k][t]) words[t * size_t(planes_) + k / 32] |= 1u << (k % 32);
    tile_views_.upload(std::span<const GLuint>(words), GL_SHADER_STORAGE_BUFFER,
                       ADAPTIVE_BINDING_LIT_TILE_VIEWS);
    tile_side_ = tiles.side();
    tile_columns_ = tiles.columns();
    tile_count_ = tiles.count();
    tiles_of_view_.assign(view_tiles.size(), {});
    for (size_t k = 0; k < view_tiles.size(); ++k)
        for (size_t t = 0; t < view_tiles[k].size(); ++t)
            if (view_tiles[k][t]) tiles_of_view_[k].push_back(std::uint32_t(t));
}

void LitBits::test(const passes::GBuffer& gbuffer, const passes::ShadowMapBatch& batch,
                   int view_base, int count, const scene::RectLight& light,
                   const CompareSettings& s) {
    // With several tiles, only the quads of those where some view of the batch is tested.
    std::vector<std::uint32_t> list;
    if (tile_count_ > 1) {
        std::vector<bool> any(size_t(tile_count_), false);
        for (int k = view_base; k < view_base + count && k < int(tiles_of_view_.size()); ++k)
            for (std::uint32_t t : tiles_of_view_[size_t(k)]) any[t] = true;
        for (size_t t = 0; t < any.size(); ++t)
            if (any[t]) list.push_back(std::uint32_t(t));
        if (list.empty()) return;
    }
    const gl::Program& program = tile_count_ > 1 ? tile_test_program_ : test_program_;
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
    glViewport(0, 0, width_, height_);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glUseProgram(program.id());
    bindMapTest(program, gbuffer, batch.depth().id(), sampler_, s, light);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, ADAPTIVE_BINDING_LIT_BITS, bits_.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, ADAPTIVE_BINDING_LIT_TILE_VIEWS, tile_views_.id());
    gl::setUniform(program, "u_planes", planes_);
    gl::setUniform(program, "u_tile_side", tile_side_);
    gl::setUniform(program, "u_tile_columns", tile_columns_);
    gl::setUniform(program, "u_view_base", view_base);
    gl::setUniform(program, "u_count", std::min(count, 32));
    gl::setUniform(program, "u_width", width_);
    gl::setUniform(program, "u_pixels", width_ * height_);
    glEnable(GL_STENCIL_TEST);  // only the pixels markLitRegion() left
    glStencilFunc(GL_EQUAL, 1, 0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    if (list.empty()) {
        fullscreen_.draw();
    } else {
        gl::setUniform(program, "u_viewport", glm::vec2(float(width_), float(height_)));
        tile_list_.upload(std::span<const std::uint32_t>(list), GL_SHADER_STORAGE_BUFFER,
                          ADAPTIVE_BINDING_LIT_TILE_LIST);
        if (!quads_vao_) quads_vao_ = gl::createVertexArray("adaptive lit tile quads");
        glBindVertexArray(quads_vao_.id());
        glDrawArrays(GL_TRIANGLES, 0, GLsizei(6 * list.size()));
        glBindVertexArray(0);
    }
    glDisable(GL_STENCIL_TEST);
    // The next batch's test ORs into the same words; the readback and evaluation read them.
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
    glBindSampler(ADAPTIVE_UNIT_COMPARE_MAPS, 0);
    glUseProgram(0);
}

ShadowBits LitBits::read(int views, int stride) const {
    stride = std::max(stride, 1);
    const int w = (width_ + stride - 1) / stride, h = (height_ + stride - 1) / stride;
    const size_t plane = size_t(width_) * size_t(height_);
    ShadowBits out;
    out.pixels = size_t(w) * size_t(h);
    out.words = std::clamp((views + 31) / 32, 1, planes_);
    out.scale = double(stride) * double(stride);
    out.bits.resize(out.pixels * size_t(out.words));
    if (stride == 1) {  // the buffer's layout, word-major: no gather
        glGetNamedBufferSubData(bits_.id(), 0, GLsizeiptr(out.bits.size() * sizeof(GLuint)),
                                out.bits.data());
        out.index();
        return out;
    }
    std::vector<GLuint> all(plane * size_t(out.words));
    glGetNamedBufferSubData(bits_.id(), 0, GLsizeiptr(all.size() * sizeof(GLuint)), all.data());
    for (int k = 0; k < out.words; ++k)
        for (int y = 0; y < h; ++y) {
            const size_t sy = size_t(std::min(y * stride + stride / 2, height_ - 1));
            for (int x = 0; x < w; ++x) {
                const size_t sx = size_t(std::min(x * stride + stride / 2, width_ - 1));
                out.bits[size_t(k) * out.pixels + size_t(y) * size_t(w) + size_t(x)] =
                    all[size_t(k) * plane + sy * size_t(width_) + sx];
            }
        }
    out.index();
    return out;
}

void LitBits::evaluate(GLuint framebuffer, const passes::GBuffer& gbuffer, int count,
                       const scene::RectLight& light, const gl::Buffer& caster_flags,
                       const ScreenTiles& tiles, const TileWeights& weights) {
    glBindTextureUnit(UNIT_ACCUMULATE_POSITION, gbuffer.position().id());
    glBindTextureUnit(UNIT_ACCUMULATE_NORMAL, gbuffer.normal().id());
    glBindTextureUnit(UNIT_ACCUMULATE_ID, gbuffer.id().id());
    gbuffer.bindGeometricNormal();
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, passes::kBindingCasterFlags, caster_flags.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, ADAPTIVE_BINDING_LIT_BITS, bits_.id());
    std::vector<std::uint32_t> tile_blocks;
    const std::vector<std::uint32_t> blocks = weights.blocks(tile_blocks);
    tile_sets_.upload(std::span<const std::uint32_t>(tile_blocks), GL_SHADER_STORAGE_BUFFER,
                      ADAPTIVE_BINDING_LIT_TILE_SETS);
    weights_.upload(std::span<const std::uint32_t>(blocks), GL_SHADER_STORAGE_BUFFER,
                    ADAPTIVE_BINDING_LIT_WEIGHTS);
    const auto draw = [&](const gl::Program& p) {
        glUseProgram(p.id());
        gl::setUniform(p, "u_count", std::min(count, capacity()));
        gl::setUniform(p, "u_width", width_);
        gl::setUniform(p, "u_pixels", width_ * height_);
        gl::setUniform(p, "u_tile_side", tiles.side());
        gl::setUniform(p, "u_tile_columns", tiles.columns());
        passes::setLightFrameUniforms(p, light);
        fullscreen_.draw();
    };
    // The pixels every view lights first (most of an image), then the others.
    eval_depth_.attach(framebuffer, width_, height_);
    passes::drawInTurn({[&] { draw(settle_program_); }, [&] { draw(eval_program_); }});
    passes::CoverDepth::detach(framebuffer);
    glUseProgram(0);
}

}  // namespace penumbra::techniques::adaptive
