// `adaptive`: two shadow maps compared over a G-buffer, counted by an occlusion query and by
// per-tile atomic counters; see map_compare.h.
#include "renderer/techniques/adaptive/map_compare.h"
#include "glsl/techniques/adaptive/bindings.glsl"

#include <algorithm>

#include "renderer/passes/bindings.h"

namespace penumbra::techniques::adaptive {
unsigned createRawDepthSampler() {
    unsigned sampler = 0;
    glCreateSamplers(1, &sampler);
    glSamplerParameteri(sampler, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glSamplerParameteri(sampler, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glSamplerParameteri(sampler, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glSamplerParameteri(sampler, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glSamplerParameteri(sampler, GL_TEXTURE_COMPARE_MODE, GL_NONE);
    return sampler;
}

void bindReceiverTest(const gl::Program& program, const passes::GBuffer& gbuffer,
                      const CompareSettings& s) {
    glBindTextureUnit(ADAPTIVE_UNIT_COMPARE_POSITION, gbuffer.position().id());
    glBindTextureUnit(ADAPTIVE_UNIT_COMPARE_NORMAL, gbuffer.normal().id());
    glBindTextureUnit(ADAPTIVE_UNIT_COMPARE_ID, gbuffer.id().id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, passes::kBindingCasterFlags, s.caster_flags);
    gl::setUniform(program, "u_normal_offset", s.normal_offset);
}

void bindMapTest(const gl::Program& program, const passes::GBuffer& gbuffer, GLuint maps,
                 unsigned sampler, const CompareSettings& s, const scene::RectLight& light) {
    bindReceiverTest(program, gbuffer, s);
    glBindTextureUnit(ADAPTIVE_UNIT_COMPARE_MAPS, maps);
    glBindSampler(ADAPTIVE_UNIT_COMPARE_MAPS, sampler);
    gl::setUniform(program, "u_depth_bias", s.depth_bias);
    passes::setLightFrameUniforms(program, light);
}

MapCompare::MapCompare()
    : program_(gl::buildProgram("adaptive compare",
                                {"passes/fullscreen.vert", "techniques/adaptive/compare.frag"})),
      bits_program_(
          gl::buildProgram("adaptive shadow bits",
                           {"passes/fullscreen.vert", "techniques/adaptive/shadow_bits.frag"})) {
    sampler_ = createRawDepthSampler();
}

MapCompare::~MapCompare() {
    glDeleteSamplers(1, &sampler_);
}

void MapCompare::begin(const passes::GBuffer& gbuffer, const passes::ShadowMapBatch& maps,
                       const scene::RectLight& light, const CompareSettings& s, int count) {
    used_ = 0;
    tiles_ = 0;
    resize(gbuffer, s.stride);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
    glViewport(0, 0, width_, height_);
    if (s.tile_size > 0) {
        const int tx = (gbuffer.width() + s.tile_size - 1) / s.tile_size;
        const int ty = (gbuffer.height() + s.tile_size - 1) / s.tile_size;
        tiles_ = tx * ty;
        const size_t need = size_t(tiles_) * size_t(std::max(count, 1));
        if (need > tile_capacity_ || !tile_counts_.id()) {
            tile_counts_ = gl::createBuffer("adaptive tile counts");
            glNamedBufferData(tile_counts_.id(), GLsizeiptr(need * sizeof(GLuint)), nullptr,
                              GL_DYNAMIC_READ);
            tile_capacity_ = need;
        }
        const GLuint zero = 0;
        glClearNamedBufferSubData(tile_counts_.id(), GL_R32UI, 0, GLsizeiptr(need * sizeof(GLuint)),
                                  GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, ADAPTIVE_BINDING_COMPARE_TILE_COUNTS,
                         tile_counts_.id());
        gl::setUniform(program_, "u_tiles_x", tx);
    }
    glUseProgram(program_.id());
    bindMapTest(program_, gbuffer, maps.depth().id(), sampler_, s, light);
    gl::setUniform(program_, "u_tile_size", tiles_ > 0 ? s.tile_size : 0);
    gl::setUniform(program_, "u_stride", stride_);
    gl::setUniform(program_, "u_gamma", s.gamma);
    gl::setUniform(program_, "u_relative", s.relative ? 1 : 0);
    gl::setUniform(program_, "u_tests", s.tests ? 1 : 0);
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_BLEND);
    glBlendEquation(GL_MAX);
    glBlendFunc(GL_ONE, GL_ONE);
}

void MapCompare::resize(const passes::GBuffer& gbuffer, int stride) {
    stride_ = std::max(stride, 1);
    const int w = (gbuffer.width() + stride_ - 1) / stride_;
    const int h = (gbuffer.height() + stride_ - 1) / stride_;
    if (w == width_ && h == height_ && levels_.id()) return;
    levels_ = gl::createTexture2D(GL_R32F, w, h, "adaptive comparison levels");
    fbo_ = gl::createFramebuffer("adaptive comparisons");
    glNamedFramebufferTexture(fbo_.id(), GL_COLOR_ATTACHMENT0, levels_.id(), 0);
    bits_ = gl::createTexture2D(GL_RGBA32UI, w, h, "adaptive shadow bits");
    bits_fbo_ = gl::createFramebuffer("adaptive shadow bits");
    glNamedFramebufferTexture(bits_fbo_.id(), GL_COLOR_ATTACHMENT0, bits_.id(), 0);
    width_ = w;
    height_ = h;
    clearLevels();
}

ShadowBits MapCompare::shadowBits(const passes::GBuffer& gbuffer,
                                  const passes::ShadowMapBatch& maps, const scene::RectLight& light,
                                  const CompareSettings& s, const std::vector<int>& views) {
    constexpr int kPerPass = 128;  // shadow_bits.frag's uvec4
    resize(gbuffer, s.stride);
    ShadowBits out;
    out.pixels = size_t(width_) * size_t(height_);
    const int passes = std::max(1, (int(views.size()) + kPerPass - 1) / kPerPass);
    out.words = 4 * passes;
    out.scale = double(stride_) * double(stride_);
    out.bits.assign(out.pixels * size_t(out.words), 0u);
    glBindFramebuffer(GL_FRAMEBUFFER, bits_fbo_.id());
    glViewport(0, 0, width_, height_);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glUseProgram(bits_program_.id());
    bindMapTest(bits_program_, gbuffer, maps.depth().id(), sampler_, s, light);
    gl::setUniform(bits_program_, "u_stride", stride_);
    std::vector<GLuint> chunk(out.pixels * 4);
    for (int k = 0; k < passes; ++k) {
        const int first = k * kPerPass;
        const int count = std::min(kPerPass, int(views.size()) - first);
        gl::setUniform(bits_program_, "u_count", count);
        glProgramUniform1iv(bits_program_.id(), glGetUniformLocation(bits_program_.id(), "u_list"),
                            count, views.data() + first);
        const GLuint zero[4] = {0, 0, 0, 0};
        glClearNamedFramebufferuiv(bits_fbo_.id(), GL_COLOR, 0, zero);
        fullscreen_.draw();
        glGetTextureImage(bits_.id(), 0, GL_RGBA_INTEGER, GL_UNSIGNED_INT,
                          GLsizei(chunk.size() * sizeof(GLuint)), chunk.data());
        for (size_t p = 0; p < out.pixels; ++p)
            for (size_t w = 0; w < 4; ++w)
                out.bits[(size_t(4 * k) + w) * out.pixels + p] = chunk[4 * p + w];
    }
    glBindSampler(ADAPTIVE_UNIT_COMPARE_MAPS, 0);
    glUseProgram(0);
    out.index();
    return out;
}

void MapCompare::raiseLevels(const std::vector<std::uint32_t>& pixels, int level) {
    raised_.resize(size_t(width_) * size_t(height_), 0.0f);
    for (std::uint32_t p : pixels)
        if (p < raised_.size()) raised_[p] = std::max(raised_[p], float(level + 1));
    glTextureSubImage2D(levels_.id(), 0, 0, 0, width_, height_, GL_RED, GL_FLOAT, raised_.data());
}

void MapCompare::compare(int a, int b, int level) {
    queue(0, {a, b, a, b}, level);
}

void MapCompare::countShadowed(std::array<int, 4> views) {
    queue(1, views, 0);
}

void MapCompare::queue(int mode, std::array<int, 4> views, int level) {
    if (used_ == static_cast<int>(queries_.size()))
        queries_.push_back(gl::createQuery(GL_SAMPLES_PASSED, "adaptive comparison"));
    const int q = used_++;
    gl::setUniform(program_, "u_mode", mode);
    gl::setUniform(program_, "u_view_a", views[0]);
    gl::setUniform(program_, "u_view_b", views[1]);
    gl::setUniform(program_, "u_view_c", views[2]);
    gl::setUniform(program_, "u_view_d", views[3]);
    gl::setUniform(program_, "u_level", level);
    // Mode 1 counts no tiles (its slot stays zero).
    gl::setUniform(program_, "u_tile_slot", q * tiles_);
    glBeginQuery(GL_SAMPLES_PASSED, queries_[static_cast<size_t>(q)].id());
    fullscreen_.draw();
    glEndQuery(GL_SAMPLES_PASSED);
}

std::vector<CompareResult> MapCompare::end() {
    glBlendEquation(GL_FUNC_ADD);
    glDisable(GL_BLEND);
    glBindSampler(ADAPTIVE_UNIT_COMPARE_MAPS, 0);
    glUseProgram(0);
    const double scale = double(stride_) * double(stride_);
    std::vector<CompareResult> out(static_cast<size_t>(used_));
    for (int i = 0; i < used_; ++i) {
        GLuint v = 0;
        glGetQueryObjectuiv(queries_[static_cast<size_t>(i)].id(), GL_QUERY_RESULT, &v);
        out[size_t(i)].pixels = double(v) * scale;
    }
    if (tiles_ > 0 && used_ > 0) {
        glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
        std::vector<GLuint> counts(size_t(tiles_) * size_t(used_));
        glGetNamedBufferSubData(tile_counts_.id(), 0, GLsizeiptr(counts.size() * sizeof(GLuint)),
                                counts.data());
        for (size_t i = 0; i < counts.size(); ++i) {
            auto& r = out[i / size_t(tiles_)];
            r.max_tile = std::max(r.max_tile, double(counts[i]) * scale);
        }
    }
    return out;
}

void MapCompare::writeLevels(GLuint dst) const {
    const GLenum only[2] = {GL_NONE, GL_COLOR_ATTACHMENT1};
    glNamedFramebufferDrawBuffers(dst, 2, only);
    glNamedFramebufferReadBuffer(fbo_.id(), GL_COLOR_ATTACHMENT0);
    // Nearest scaling by the stride: each comparison pixel covers its block (the edge blocks
    // of a size that is no multiple of the stride spill past the image and are clipped).
    glBlitNamedFramebuffer(fbo_.id(), dst, 0, 0, width_, height_, 0, 0, width_ * stride_,
                           height_ * stride_, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    const GLenum all[2] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    glNamedFramebufferDrawBuffers(dst, 2, all);
}

void MapCompare::clearLevels() {
    std::fill(raised_.begin(), raised_.end(), 0.0f);
    if (!levels_.id()) return;  // begin() creates them cleared
    const float zero = 0.0f;
    glClearTexImage(levels_.id(), 0, GL_RED, GL_FLOAT, &zero);
}

}  // namespace penumbra::techniques::adaptive
