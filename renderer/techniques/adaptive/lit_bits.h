// `adaptive`: every light-sample map's hard test at every G-buffer pixel, kept as one bit per map
// for the whole light, so that maps are rendered in small batches, tested once and dropped.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <vector>

#include "renderer/gl/dynamic_buffer.h"
#include "renderer/gl/handles.h"
#include "renderer/gl/program.h"
#include "renderer/passes/cover_depth.h"
#include "renderer/passes/fullscreen.h"
#include "renderer/passes/gbuffer.h"
#include "renderer/passes/light_windows.h"
#include "renderer/passes/shadow_maps.h"
#include "renderer/scene/scene.h"
#include "renderer/techniques/adaptive/map_compare.h"
#include "renderer/techniques/adaptive/screen_tiles.h"
#include "renderer/techniques/adaptive/shadow_bits.h"

namespace penumbra::techniques::adaptive {

// The casters seen from the light's centre: a min/max pyramid of their distances from the
// light's plane (RG32F mips, passes::DistancePyramid) through WINDOW.
struct LitRegion {
    GLuint pyramid = 0;
    int size = 0, levels = 0;
    passes::LightWindow window;
};

// The bits (set: shadowed) of up to 32 x planes views per pixel, in a storage buffer (plane-major,
// lit_bits.frag); the comparisons read them back at a stride and lit_eval.frag weights them.
class LitBits {
public:
    LitBits();
    ~LitBits();
    LitBits(const LitBits&) = delete;
    LitBits& operator=(const LitBits&) = delete;

    // Sizes the bits for GBUFFER and at most VIEWS views, all clear (lit everywhere), and marks
    // every pixel for test().
    void begin(const passes::GBuffer& gbuffer, int views);
    // Marks the pixels of GBUFFER some caster in REGION may shadow (lit_region.frag, at the
    // tests' points: S's normal offset in texels of TEXEL_SIZE per unit distance): test()
    // tests only those until the next begin().
    void markLitRegion(const passes::GBuffer& gbuffer, const scene::RectLight& light,
                       const CompareSettings& s, float texel_size, const LitRegion& region);
    // The pixels markLitRegion() marked since begin() (blocking); none when it was not called.
    std::optional<double> markedPixels() const;
    // The tiles of TILES that hold a pixel of GBUFFER on a caster whose tangent plane cuts
    // LIGHT (horizon_tiles.frag; blocking).
    TileMask horizonTiles(const passes::GBuffer& gbuffer, const scene::RectLight& light,
                          const gl::Buffer& caster_flags, const ScreenTiles& tiles);
    // The views test() tests in each of TILES' tiles: VIEW_TILES[k] is view k's (as many as
    // the views to test next; views past them are tested nowhere).
    void setTestedTiles(const ScreenTiles& tiles, std::span<const TileMask> view_tiles);
    // Sets the bits of views VIEW_BASE..VIEW_BASE+COUNT-1 (COUNT at most 32), held in BATCH's
    // layers 0..COUNT-1 (views bound at kBindingSampleViews/kBindingSampleLookups): hard tests
    // with SETTINGS' offset and bias, the normal offset from view 0 as the evaluation's, in the
    // tiles setTestedTiles() gave each view (drawn as those tiles' quads when there are several).
    void test(const passes::GBuffer& gbuffer, const passes::ShadowMapBatch& batch, int view_base,
              int count, const scene::RectLight& light, const CompareSettings& settings);
    // Views 0..VIEWS-1 at the centre pixel of every STRIDE x STRIDE block (as shadow_bits.frag
    // samples them), slot = view (blocking).
    ShadowBits read(int views, int stride) const;
    // Adds sum_k w_k lit_k over views 0..COUNT-1 and the beauty sums into colour 0 of
    // FRAMEBUFFER (bound), as passes::ShadowAccumulate with pcf 1 (the caller sets the blending),
    // with each of TILES' tiles' weights from WEIGHTS (count views a set); a depth attachment
    // of its own is on FRAMEBUFFER meanwhile.
    void evaluate(GLuint framebuffer, const passes::GBuffer& gbuffer, int count,
                  const scene::RectLight& light, const gl::Buffer& caster_flags,
                  const ScreenTiles& tiles, const TileWeights& weights);
    // The views whose bits begin() made room for (evaluate() reads at most these).
    int capacity() const { return 32 * planes_; }

private:
    gl::Program test_program_;
    gl::Program tile_test_program_;  // the same over tile_quads.vert's tiles
    gl::Program eval_program_;
    gl::Program settle_program_;  // lit_eval.frag's SETTLE variant, drawn before eval_program_
    passes::CoverDepth eval_depth_{"adaptive evaluation cover"};
    passes::Fullscreen fullscreen_;
    gl::Framebuffer fbo_;  // the G-buffer's size, only a stencil: for the test passes
    gl::Buffer bits_;
    gl::DynamicBuffer tile_views_{"adaptive lit tile views"};  // setTestedTiles()'s
    gl::DynamicBuffer tile_list_{"adaptive lit tile list"};    // test()'s batch's tiles
    std::vector<std::vector<std::uint32_t>> tiles_of_view_;    // setTestedTiles()'s, per view
    gl::VertexArray quads_vao_;
    gl::DynamicBuffer tile_sets_{"adaptive lit tile sets"};  // evaluate()'s
    gl::DynamicBuffer weights_{"adaptive lit weights"};
    int tile_side_ = 1, tile_columns_ = 1, tile_count_ = 1;  // setTestedTiles()'s
    gl::Program region_program_;
    gl::Program horizon_program_;
    gl::DynamicBuffer horizon_tiles_{"adaptive horizon tiles"};  // horizonTiles()'s
    gl::Texture stencil_;                                        // 1: the pixels test() shades
    gl::Query marked_;                                           // markLitRegion()'s pixels
    bool region_marked_ = false;                                 // markLitRegion() since begin()
    size_t capacity_ = 0;                                        // words in bits_
    int width_ = 0, height_ = 0, planes_ = 0;
    unsigned sampler_ = 0;  // nearest, no depth compare: raw depths of the maps
};

}  // namespace penumbra::techniques::adaptive
