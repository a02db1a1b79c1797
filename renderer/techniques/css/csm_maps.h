// The prefiltered maps of `css` for one light: a linear-depth shadow map from the light's
// centre (and one of the casters' farthest surfaces), its CSM and CSM-Z basis
// (glsl/techniques/css/basis.comp), prefiltered by mipmaps or summed-area tables.
#pragma once

#include <memory>

#include "renderer/gl/handles.h"
#include "renderer/gl/program.h"
#include "renderer/passes/gpu_scene.h"
#include "renderer/passes/light_depth.h"
#include "renderer/passes/light_windows.h"
#include "renderer/passes/summed_area_table.h"

namespace penumbra::techniques::css {

// Layers of the basis array for order M: ceil(M/2) CSM, ceil(M/2) CSM-Z, one z.
constexpr int basisLayers(int order) {
    return 2 * ((order + 1) / 2) + 1;
}

// The depth normalisation's margin for order M and ring shift SHIFT: min(SHIFT + 0.5 / M,
// 0.3). The Fourier test is periodic (period 2 in d - z) and rings across a band of about
// 1 / (2M) around its jumps at d - z = 0 and -1; real depths fill [m, 1 - m] and empty texels
// hold 1, so every receiver against an empty texel (d - 1 in [m - 1, -m], evaluated at
// d - shift) stays clear of both.
float depthMargin(int order, float shift);

// The light-centred view of the map: the casters' window (x, y), with a depth range from the
// nearest caster to the farthest point of the scene or, where that lies farther, to a gap
// past the farthest caster (the normalised share MARGIN, depthMargin(), and at least a
// quarter of the farthest caster's distance: csm_maps.cpp): receivers beyond the
// gap take its depth (DepthRange::receiver_max), behind every caster either way, so a scene's
// extent behind its casters (a long floor under a low light) does not spend the depth
// resolution that the series needs between a caster and the receiver behind it.
passes::LightWindow mapWindow(const scene::RectLight& light, passes::Boxes casters,
                              passes::Boxes scene, float margin);

// The depth normalisation of the map for WINDOW (mapWindow() with the same MARGIN): its near
// and far land on MARGIN and 1 - MARGIN (depthMargin()).
struct DepthRange {
    float near = 0.0f, far = 1.0f;  // distances along the light's forward axis of depth 0 and 1
    float receiver_max = 1.0f;      // the normalised depth receivers are clamped to: 1 - m
};
DepthRange depthRange(const passes::LightWindow& window, float margin);

class CsmMaps {
public:
    enum class Filter { Mipmap, Sat };
    // Resources for a MAP_SIZE^2 map of order ORDER; SAT and MIPMAP say which prefilters to
    // prepare (both when a scene mixes square and rectangular lights). MIDDLE_AT > 0: the CSM-Z
    // basis weights each texel by the depth that far from its nearest (0) to its farthest (1)
    // caster surface instead of the nearest (a second, farthest-surface map); 0: the nearest.
    CsmMaps(int map_size, int order, bool mipmap, bool sat, float middle_at);

    // The caster depth map seen through WINDOW (and with MIDDLE_AT the farthest surfaces', in
    // the same draw).
    void renderDepth(const passes::GpuScene& scene, const scene::RectLight& light,
                     const passes::LightWindow& window, const DepthRange& range);
    // The basis of the depth map (centred on their empty-texel values) for FILTER: with
    // mipmaps the basis images; with summed-area tables the running sums of their rows,
    // straight into the table (the images are not stored).
    void buildBasis(Filter filter);
    // Prefilters the basis with FILTER (after buildBasis(FILTER)): the mipmaps, or the table's
    // column sums; filtered(FILTER) is then ready for lookups.
    void prefilter(Filter filter);
    const gl::Texture& filtered(Filter filter) const;
    // For the mipmap's blocker searches: bilinear within the nearest level (half the texels
    // of trilinear filtering; an average depth needs less than the final test).
    const gl::Sampler& searchSampler() const { return search_sampler_; }

    int mapSize() const { return map_size_; }

private:
    int map_size_, layers_;
    std::unique_ptr<passes::LightDepthTarget> depth_;       // the nearest surfaces, or
    std::unique_ptr<passes::LightDepthRangeTarget> range_;  // with middle_at, both in one draw

    gl::Texture basis_;  // mipmapped (written only for the mipmaps)
    gl::Sampler search_sampler_;
    std::unique_ptr<passes::SummedAreaTable> sat_;
    passes::LightDepthPass depth_pass_;
    gl::Program basis_program_, sat_rows_program_;  // basis.comp, SAT_ROWS 0 and 1
    float middle_at_;
};

}  // namespace penumbra::techniques::css
