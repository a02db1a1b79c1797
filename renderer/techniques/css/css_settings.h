// The parameters of `css` (the table behind -D, the scene's technique block and `penumbra
// techniques`), their resolved form, and the prefilter chosen for a light.
#pragma once

#include <array>
#include <cstdint>

#include "renderer/core/memory_term.h"
#include "renderer/core/params.h"
#include "renderer/scene/scene.h"
#include "renderer/techniques/css/csm_maps.h"
#include "renderer/techniques/environment_lights.h"
#include "renderer/techniques/param_keys.h"

namespace penumbra::techniques::css {

// In the order of the `filter` parameter's choices.
enum class FilterChoice { Sat, Mipmap, Auto };
inline constexpr EnumKey<FilterChoice, 3> kFilter{"filter", {"sat", "mipmap", "auto"}};
// In the order of the `blocker_depth` parameter's choices.
enum class BlockerDepth { Middle, Nearest };
inline constexpr EnumKey<BlockerDepth, 2> kBlockerDepth{"blocker_depth", {"middle", "nearest"}};

// ORDER, MAX_ANISO, MIP_TAPS and SEARCH_STEPS are the visibility program's #defines; the
// environment's rows are environment_lights.h's.
inline constexpr IntKey kOrder{"order"};
inline constexpr IntKey kMaxAniso{"max_aniso"};
inline constexpr IntKey kMipTaps{"mip_taps"};
inline constexpr IntKey kSearchSteps{"search_steps"};
inline constexpr FloatKey kRingScale{"ring_scale"};
inline constexpr FloatKey kRingShift{"ring_shift"};
inline constexpr FloatKey kMiddleAt{"middle_at"};
inline constexpr FloatKey kRingPlateau{"ring_plateau"};
inline constexpr FloatKey kSharpenA{"sharpen_a"};
inline constexpr FloatKey kSharpenB{"sharpen_b"};
inline constexpr FloatKey kSelfExclude{"self_exclude"};
inline constexpr FloatKey kInterpolate{"interpolate"};

inline constexpr std::array kCssParams = joinParams(
    std::array{
        intParam(kOrder, 4, 1, 16, "M: Fourier terms of the shadow-test expansion").define(),
        intParam(kMapSize, 256, 16, 4096, "shadow map (and basis image) width and height in texels")
            .limitedBy(GlLimit::MaxTextureSize),
        enumParam(kFilter, FilterChoice::Sat,
                  "prefilter: summed-area tables, mipmaps, or auto (the paper's choice: mipmaps "
                  "for square lights, SATs for rectangular ones)"),
        intParam(kMaxAniso, 8, 1, 16,
                 "mipmap taps along the longer axis of a rectangular light's kernel (anisotropy)")
            .define(),
        intParam(kMipTaps, 2, 1, 4,
                 "mipmap taps per side of a square kernel (1 = the paper's single trilinear "
                 "lookup)")
            .define(),
        enumParam(kBlockerDepth, BlockerDepth::Middle,
                  "the depth the blocker search averages: per map texel a depth between the "
                  "nearest and the farthest caster surface (middle_at), or the nearest (the "
                  "paper's shadow map)"),
        floatParam(kMiddleAt, 0.35, 0.05, 1.0,
                   "blocker_depth middle: the depth a texel gives the blocker search, this far "
                   "from its nearest (0) to its farthest (1) caster surface (0.5: a ball's "
                   "silhouette)"),
        intParam(kSearchSteps, 2, 0, 4,
                 "blocker searches after the first, each over the cone cut at the last z_avg (0 "
                 "= the paper's one search at the near plane)")
            .define(),
        floatParam(kRingScale, 1.0, 0.5, 8.0,
                   "ringing suppression: the filtered test is scaled by this about 1/2, then "
                   "clamped")
            .uniform(),
        floatParam(kRingShift, 0.08, 0.0, 0.5,
                   "ringing suppression: the test is evaluated this far (normalised depth) nearer "
                   "the light, so a surface does not shadow itself")
            .uniform(),
        floatParam(kRingPlateau, 0.05, 0.0, 0.25,
                   "ringing suppression: the final test is divided by the series' value at the "
                   "kernel's mean caster depth when that lies this far (normalised depth) in "
                   "front of the test depth, fully from twice as far, so an umbra is black (0 = "
                   "off, the paper's)")
            .uniform(),
        floatParam(kSharpenA, 30.0, 0.0, 1000.0,
                   "contact sharpening strength A in v^p, p = 1 + A exp(-B (d - z_avg)); 0 = off")
            .uniform(),
        floatParam(kSharpenB, 30.0, 0.0, 10000.0,
                   "contact sharpening falloff B (per unit of normalised depth)")
            .uniform(),
        floatParam(kSelfExclude, 0.25, 0.0, 1.0,
                   "a receiver that casts is tested this share of each kernel's half-width "
                   "nearer the light along its own tangent plane, so its own surface is not its "
                   "blocker (0 = off, 1 = the whole kernel)")
            .uniform(),
        floatParam(kInterpolate, 0.05, 0.0, 1.0,
                   "evaluate every other pixel and interpolate a pixel whose samples lie on its "
                   "object and spread by at most this in shadow (0 = evaluate every pixel; with "
                   "SATs only: with mipmaps every pixel is evaluated)")
            .uniform(),
    },
    kFittedEnvironmentParams);

struct CssSettings {
    int order = 4;
    int map_size = 256;
    using FilterChoice = css::FilterChoice;
    FilterChoice filter = FilterChoice::Sat;
    BlockerDepth blocker_depth = BlockerDepth::Middle;
    float middle_at = 0.35f;
    int max_aniso = 8;
    int mip_taps = 2;
    int search_steps = 2;
    float ring_scale = 1.0f, ring_shift = 0.08f;
    float sharpen_a = 30.0f, sharpen_b = 30.0f;
    float self_exclude = 0.25f;
    float interpolate = 0.05f;
};

CssSettings cssSettings(const Params& params);

// css's largest allocations for the memory budget: the basis images (with their mipmaps, or
// their summed-area tables) and the shadow map.
MemoryTerms memoryTerms(const Params& p, std::uint64_t pixels);

// The prefilter for LIGHT: the chosen one, or with `auto` mipmaps for a square light and
// summed-area tables for a rectangular one.
CsmMaps::Filter filterFor(const CssSettings& settings, const scene::RectLight& light);

}  // namespace penumbra::techniques::css
