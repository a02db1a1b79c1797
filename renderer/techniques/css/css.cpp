// `css`: convolution soft shadows (Annen et al. 2008). A light-centred shadow map is expanded
// into Fourier basis images (CSM) and depth-weighted ones (CSM-Z), prefiltered by mipmaps or
// summed-area tables; each pixel finds its average blocker depth and filters the shadow test
// with a kernel of the penumbra's width (glsl/techniques/css/visibility.glsl), only where a
// caster lies under its search kernel; with `interpolate`, at every other pixel first and at
// the rest only where interpolation is unsafe.
#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "glsl/techniques/css/bindings.glsl"
#include "renderer/gl/param_uniforms.h"
#include "renderer/passes/bindings.h"
#include "renderer/passes/cover_depth.h"
#include "renderer/passes/fullscreen.h"
#include "renderer/passes/shadow_maps.h"
#include "renderer/techniques/css/csm_maps.h"
#include "renderer/techniques/css/css_settings.h"
#include "renderer/techniques/environment_lights.h"
#include "renderer/techniques/registry_entries.h"

namespace penumbra::techniques {
namespace {

using css::CsmMaps;

class Css final : public Technique {
public:
    explicit Css(const Params& p) : params_(p), settings_(css::cssSettings(p)) {}

    void prepare(const gl::ContextInfo&, const passes::GpuScene&) override {
        maps_.reset();
        programs_ = {};
        coarse_ = {};
    }

    void render(frame::FrameContext& ctx) override {
        const scene::RectLight& light = ctx.currentLight();
        const CsmMaps::Filter filter = css::filterFor(settings_, light);
        ensureResources(filter);
        const float margin = css::depthMargin(settings_.order, settings_.ring_shift);
        const passes::LightWindow window =
            css::mapWindow(light, ctx.gpu.casterBoxes(), ctx.gpu.sceneBoxes(), margin);
        const css::DepthRange range = css::depthRange(window, margin);
        if (!window.empty()) {
            ctx.pass("css_shadow_map", [&] { maps_->renderDepth(ctx.gpu, light, window, range); });
            ctx.pass("css_basis", [&] { maps_->buildBasis(filter); });
            ctx.pass(filter == CsmMaps::Filter::Sat ? "css_sat" : "css_mipmap",
                     [&] { maps_->prefilter(filter); });
        }
        ctx.pass("css_visibility", [&] {
            uploadObjectNearest(ctx.gpu, light, range);
            visibility(ctx, light, window, range, filter);
        });
        ctx.stats["maps_rendered"] = ctx.stats.value("maps_rendered", 0) + (window.empty() ? 0 : 1);
        ctx.stats["order"] = settings_.order;
    }

    std::vector<DiagnosticChannel> diagnostics() const override {
        return {{"z_avg", DiagnosticChannel::Combine::Max},
                {"filter_width", DiagnosticChannel::Combine::Max}};
    }

private:
    // Maps and programs on first use: a scene of square lights never builds SAT resources.
    void ensureResources(CsmMaps::Filter filter) {
        const bool sat = filter == CsmMaps::Filter::Sat;
        Programs& programs = programs_[sat ? 1 : 0];
        if (!maps_ || (sat && !has_sat_) || (!sat && !has_mipmap_)) {
            has_sat_ |= sat;
            has_mipmap_ |= !sat;
            maps_ = std::make_unique<CsmMaps>(
                settings_.map_size, settings_.order, has_mipmap_, has_sat_,
                settings_.blocker_depth == css::BlockerDepth::Middle ? settings_.middle_at : 0.0f);
        }
        if (!programs.every) {
            // ORDER, MAX_ANISO, MIP_TAPS, SEARCH_STEPS from the table; FILTER_SAT per light.
            gl::Defines defines = gl::paramDefines(css::kCssParams, params_);
            defines.emplace_back("FILTER_SAT", sat ? "1" : "0");
            const auto build = [&](const char* label, const char* fragment,
                                   const char* coarse = nullptr) {
                gl::Defines d = defines;
                if (coarse) d.emplace_back("COARSE", coarse);
                return gl::buildProgram(label, {"passes/fullscreen.vert", fragment}, d);
            };
            const char* cover = "techniques/css/visibility_cover.frag";
            programs.every = build("css visibility", "techniques/css/visibility.frag");
            if (sat) programs.cover = build("css visibility cover", cover, "0");
            if (sat && settings_.interpolate > 0.0f) {
                programs.coarse =
                    build("css visibility coarse", "techniques/css/visibility_coarse.frag");
                programs.fine = build("css visibility fine", "techniques/css/visibility_fine.frag");
                programs.settled =
                    build("css visibility settled", "techniques/css/visibility_settled.frag");
                programs.coarse_cover = build("css visibility coarse cover", cover, "1");
            }
        }
    }

    // Per object id, the nearest depth of its world bounds from LIGHT's centre, normalised as
    // the map's (visibility.glsl: a receiver's own surface is no nearer, whatever its plane).
    void uploadObjectNearest(const passes::GpuScene& gpu, const scene::RectLight& light,
                             const css::DepthRange& range) {
        std::vector<float> nearest(1, 0.0f);
        const glm::vec3 forward = light.forward();
        for (const passes::GpuObject& o : gpu.objects()) {
            float z = 1e30f;
            for (int i = 0; i < 8; ++i)
                z = std::min(z, glm::dot(o.world_box.corner(i) - light.position, forward));
            if (nearest.size() <= size_t(o.id)) nearest.resize(size_t(o.id) + 1, 0.0f);
            nearest[size_t(o.id)] = (z - range.near) / (range.far - range.near);
        }
        if (!object_nearest_) object_nearest_ = gl::createBuffer("css object nearest");
        glNamedBufferData(object_nearest_.id(), GLsizeiptr(nearest.size() * sizeof(float)),
                          nearest.data(), GL_DYNAMIC_DRAW);
    }

    // The target of the coarse samples (every other pixel of a WIDTH x HEIGHT image), with the
    // depth of those settled (passes::drawInTurn).
    void ensureTargets(int width, int height) {
        const int w = (width + 1) / 2, h = (height + 1) / 2;
        if (coarse_.texture && coarse_.width == w && coarse_.height == h) return;
        coarse_.texture = gl::createTexture2D(GL_RGBA32F, w, h, "css coarse samples");
        coarse_.fbo = gl::createFramebuffer("css coarse samples");
        coarse_.width = w;
        coarse_.height = h;
        glNamedFramebufferTexture(coarse_.fbo.id(), GL_COLOR_ATTACHMENT0, coarse_.texture.id(), 0);
        coarse_.settled.attach(coarse_.fbo.id(), w, h);
        passes::checkFramebuffer(coarse_.fbo, "css coarse samples");
    }

    // Draws COVER (visibility_cover.frag), which writes the pixels with no caster under their
    // first search kernel and discards the others, then EVALUATE on those alone
    // (passes::drawCovered), into the bound framebuffer, whose depth attachment the caller set.
    void drawCovered(frame::FrameContext& ctx, const gl::Program& cover,
                     const gl::Program& evaluate, const scene::RectLight& light,
                     const passes::LightWindow& w, const css::DepthRange& range,
                     CsmMaps::Filter filter) {
        passes::drawCovered([&] { draw(ctx, cover, light, w, range, filter); },
                            [&] { draw(ctx, evaluate, light, w, range, filter); });
    }

    void visibility(frame::FrameContext& ctx, const scene::RectLight& light,
                    const passes::LightWindow& w, const css::DepthRange& range,
                    CsmMaps::Filter filter) {
        ctx.bindOutput();
        const float lit[4] = {1, 0, 0, 0}, zero[4] = {0, 0, 0, 0};
        glClearBufferfv(GL_COLOR, 0, lit);
        glClearBufferfv(GL_COLOR, 1, zero);
        glClearBufferfv(GL_COLOR, 2, zero);
        if (w.empty()) return;  // no caster in front of the light
        glDisable(GL_BLEND);
        glDisable(GL_DEPTH_TEST);
        const Programs& programs = programs_[filter == CsmMaps::Filter::Sat ? 1 : 0];
        if (filter != CsmMaps::Filter::Sat) {
            // Mipmaps: every pixel, unmarked. Their lookups take a level per pixel, which
            // llvmpipe samples lane by lane: the marking draw's one lookup cost more than it
            // saved (css_visibility on the default scene at 1024 x 768 146 -> 251 ms), and
            // `interpolate` 0.05 made it 2.4-4.2x slower (light_size_2 80 -> 332 ms).
            draw(ctx, programs.every, light, w, range, filter);
            return;
        }
        const GLuint output = ctx.bindOutput();
        ensureTargets(ctx.gbuffer.width(), ctx.gbuffer.height());
        coarse_.pixels.attach(output, ctx.gbuffer.width(), ctx.gbuffer.height());
        if (settings_.interpolate <= 0.0f) {
            drawCovered(ctx, programs.cover, programs.every, light, w, range, filter);
            passes::CoverDepth::detach(output);
            return;
        }
        // Every other pixel (where a caster may shadow it); the rest interpolated where safe,
        // else evaluated.
        glBindFramebuffer(GL_FRAMEBUFFER, coarse_.fbo.id());
        glViewport(0, 0, coarse_.width, coarse_.height);
        drawCovered(ctx, programs.coarse_cover, programs.coarse, light, w, range, filter);
        glBindFramebuffer(GL_FRAMEBUFFER, output);
        glViewport(0, 0, ctx.gbuffer.width(), ctx.gbuffer.height());
        glBindTextureUnit(CSS_UNIT_VISIBILITY_COARSE, coarse_.texture.id());
        // The pixels the interpolation would leave at the cleared values first (no colour:
        // visibility_settled.frag), then the interpolation, then the full evaluation of the
        // pixels it left. The fine pass costs its every line at every pixel of a block it
        // shades, whatever the pixel's branch; marking those pixels costs eight lookups:
        // css_visibility at 1024 x 768 on light_size_2 63 -> 51 ms, the same image.
        passes::drawInTurn({[&] { drawSettled(ctx, programs.settled); },
                            [&] { draw(ctx, programs.fine, light, w, range, filter); },
                            [&] { draw(ctx, programs.every, light, w, range, filter); }});
        passes::CoverDepth::detach(output);
    }

    // visibility_settled.frag's draw (P), which writes no colour and reads the G-buffer's
    // position and ids, the caster flags and the coarse samples (bound by the caller).
    void drawSettled(frame::FrameContext& ctx, const gl::Program& p) {
        glUseProgram(p.id());
        glBindTextureUnit(CSS_UNIT_VISIBILITY_POSITION, ctx.gbuffer.position().id());
        glBindTextureUnit(CSS_UNIT_VISIBILITY_ID, ctx.gbuffer.id().id());
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, passes::kBindingCasterFlags,
                         ctx.gpu.casterFlags().id());
        glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
        fullscreen_.draw();
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        glUseProgram(0);
    }

    // One full-viewport draw of P (a visibility program) into the bound framebuffer.
    void draw(frame::FrameContext& ctx, const gl::Program& p, const scene::RectLight& light,
              const passes::LightWindow& w, const css::DepthRange& range, CsmMaps::Filter filter) {
        glUseProgram(p.id());
        glBindTextureUnit(CSS_UNIT_VISIBILITY_POSITION, ctx.gbuffer.position().id());
        glBindTextureUnit(CSS_UNIT_VISIBILITY_BASIS, maps_->filtered(filter).id());
        ctx.gbuffer.bindGeometricNormal();
        glBindTextureUnit(CSS_UNIT_VISIBILITY_BASIS_SEARCH, maps_->filtered(filter).id());
        glBindSampler(CSS_UNIT_VISIBILITY_BASIS_SEARCH, maps_->searchSampler().id());
        glBindTextureUnit(CSS_UNIT_VISIBILITY_ID, ctx.gbuffer.id().id());
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, passes::kBindingCasterFlags,
                         ctx.gpu.casterFlags().id());
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, CSS_BINDING_OBJECT_NEAREST,
                         object_nearest_.id());
        passes::setLightFrameUniforms(p, light);
        gl::setUniform(p, "u_light_size", light.size);
        gl::setUniform(p, "u_window_lo", w.lo);
        gl::setUniform(p, "u_window_size", w.size);
        gl::setUniform(p, "u_near", w.near);
        gl::setUniform(p, "u_depth_near", range.near);
        gl::setUniform(p, "u_depth_far", range.far);
        gl::setUniform(p, "u_receiver_max", range.receiver_max);
        gl::setUniform(p, "u_map_size", static_cast<float>(settings_.map_size));
        // ring_*, sharpen_*, self_exclude, interpolate
        gl::setParamUniforms(p, css::kCssParams, params_);
        fullscreen_.draw();
        glBindSampler(CSS_UNIT_VISIBILITY_BASIS_SEARCH, 0);
        glUseProgram(0);
    }

    Params params_;
    css::CssSettings settings_;
    std::unique_ptr<CsmMaps> maps_;
    gl::Buffer object_nearest_;  // uploadObjectNearest()
    bool has_mipmap_ = false, has_sat_ = false;
    struct Programs {
        gl::Program every, cover;  // every pixel, after cover marks those a caster may shadow
        gl::Program coarse, fine, coarse_cover, settled;  // with `interpolate`: its passes
    };
    std::array<Programs, 2> programs_;  // mipmap, SAT
    struct Coarse {
        gl::Texture texture;
        passes::CoverDepth settled{"css settled samples"};  // those the coarse cover settled
        gl::Framebuffer fbo;
        passes::CoverDepth pixels{"css settled pixels"};  // full size: before visibility.frag
        int width = 0, height = 0;
    } coarse_;
    passes::Fullscreen fullscreen_;
};

}  // namespace

const TechniqueInfo kCssTechnique = {
    "css",
    "convolution soft shadows (Annen et al. 2008): prefiltered Fourier basis of the shadow test",
    css::kCssParams,
    [](const Params& p) -> std::unique_ptr<Technique> { return std::make_unique<Css>(p); },
    fittedEnvironmentLights,
    css::memoryTerms,
    nullptr,
    fittedEnvironmentLightsMax};

}  // namespace penumbra::techniques
