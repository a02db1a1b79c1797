// `adaptive`: the comparison of two light-sample shadow maps over a G-buffer (the camera's or
// the light centre's), disagreeing pixels counted by an occlusion query and per screen tile.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "renderer/gl/handles.h"
#include "renderer/gl/program.h"
#include "renderer/passes/fullscreen.h"
#include "renderer/passes/gbuffer.h"
#include "renderer/passes/shadow_maps.h"
#include "renderer/scene/scene.h"
#include "renderer/techniques/adaptive/shadow_bits.h"

namespace penumbra::techniques::adaptive {

struct CompareSettings {
    float gamma = 0.01f;         // largest depth difference (or ratio deviation) still equal
    bool relative = false;       // eq. 7 instead of eq. 3
    bool tests = false;          // compare hard-shadow test results instead of stored depths
    float normal_offset = 1.5f;  // of the hard tests, as in passes::ShadowTestSettings
    float depth_bias = 0.0005f;
    // GpuScene::casterFlags()'s buffer: only receivers that cast take the normal offset
    // (common/receiver_point.glsl). Set each frame.
    unsigned caster_flags = 0;
    int tile_size = 0;  // > 0: also count disagreeing pixels per screen tile of this side
    int stride = 1;     // compare every stride-th G-buffer pixel along x and y; counts x stride^2
};

// What one comparison found.
// With a stride, counts are estimates: compared pixels x stride^2.
struct CompareResult {
    double pixels = 0;    // disagreeing pixels in the frame (the occlusion query)
    double max_tile = 0;  // most disagreeing pixels in one tile (0 without tiles)
};

// A new sampler object reading the raw depths of shadow maps: nearest, clamped, no compare.
unsigned createRawDepthSampler();

// Binds where a test of G-buffer points finds its receivers, for PROGRAM (in use): the
// G-buffer's position, normal and ids, S's caster flags and normal offset (receiver_point.glsl).
void bindReceiverTest(const gl::Program& program, const passes::GBuffer& gbuffer,
                      const CompareSettings& s);

// Binds what every test of G-buffer points against shadow maps reads, for PROGRAM (in use):
// bindReceiverTest's bindings, the maps' depth array MAPS through SAMPLER (raw depths), S's
// depth bias and LIGHT's frame.
void bindMapTest(const gl::Program& program, const passes::GBuffer& gbuffer, GLuint maps,
                 unsigned sampler, const CompareSettings& s, const scene::RectLight& light);

class MapCompare {
public:
    MapCompare();
    ~MapCompare();
    MapCompare(const MapCompare&) = delete;
    MapCompare& operator=(const MapCompare&) = delete;

    // Sets up state for a series of at most COUNT comparisons of views in MAPS (layer = view
    // index, views bound at kBindingSampleViews/kBindingSampleLookups) over GBUFFER, drawn
    // into this object's framebuffer of GBUFFER's size / stride.
    void begin(const passes::GBuffer& gbuffer, const passes::ShadowMapBatch& maps,
               const scene::RectLight& light, const CompareSettings& settings, int count);
    // Queues the comparison of views A and B.
    void compare(int a, int b, int level);
    // Queues a count of the pixels that any of VIEWS shadows (hard tests; no tile counts, no
    // diagnostic level); its result comes in compare() order with the comparisons'.
    void countShadowed(std::array<int, 4> views);
    // Restores state; the results of this series, in compare() order (blocking).
    std::vector<CompareResult> end();
    // Which of VIEWS shadow every stride-th pixel of GBUFFER (hard tests with SETTINGS' offset
    // and bias; one pass per 128 views), bit i for VIEWS[i] (blocking). Series of queued
    // comparisons must not be open.
    ShadowBits shadowBits(const passes::GBuffer& gbuffer, const passes::ShadowMapBatch& maps,
                          const scene::RectLight& light, const CompareSettings& settings,
                          const std::vector<int>& views);
    // Raises the levels to LEVEL + 1 at PIXELS (indices, of the last shadowBits()).
    void raiseLevels(const std::vector<std::uint32_t>& pixels, int level);
    // Writes max(level + 1) of the disagreements of every series since the last
    // clearLevels(), scaled up by the stride, into colour 1 of framebuffer DST (whose draw
    // buffers are colours 0 and 1).
    void writeLevels(GLuint dst) const;
    // Zeroes the levels (begin() keeps them, so the series of one light accumulate).
    void clearLevels();
    // Sizes the levels (cleared when their size changes) and the bit target to GBUFFER /
    // STRIDE: raiseLevels() then takes pixel indices of a view of that size.
    void resize(const passes::GBuffer& gbuffer, int stride);

private:
    void queue(int mode, std::array<int, 4> views, int level);

    gl::Program program_;
    gl::Program bits_program_;  // shadow_bits.frag
    gl::Texture bits_;          // RGBA32UI, the size of levels_
    gl::Framebuffer bits_fbo_;
    passes::Fullscreen fullscreen_;
    gl::Texture levels_;         // R32F, the G-buffer's size / stride
    std::vector<float> raised_;  // levels_ as raiseLevels() left them
    gl::Framebuffer fbo_;
    int width_ = 0, height_ = 0, stride_ = 1;  // of levels_
    unsigned sampler_ = 0;                     // nearest, no depth compare: raw depths of the maps
    std::vector<gl::Query> queries_;
    int used_ = 0;
    int tiles_ = 0;  // tiles per comparison, 0: no tile counts this series
    gl::Buffer tile_counts_;
    size_t tile_capacity_ = 0;  // uints in tile_counts_
};

}  // namespace penumbra::techniques::adaptive
