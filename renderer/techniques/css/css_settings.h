// The parameters of `css` (the table behind -D, the scene's technique block and `penumbra
// techniques`), their resolved form, and the prefilter chosen for a light.
#pragma once

#include <array>

#include "renderer/core/params.h"
#include "renderer/scene/scene.h"
#include "renderer/techniques/css/csm_maps.h"

namespace penumbra::techniques::css {

inline constexpr std::array kCssParams = {
    intParam("order", 4, 1, 16, "M: Fourier terms of the shadow-test expansion"),
    intParam("map_size", 256, 16, 4096, "shadow map (and basis image) width and height in texels"),
    enumParam("filter", "sat", "sat|mipmap|auto",
              "prefilter: summed-area tables, mipmaps, or auto (the paper's choice: mipmaps for "
              "square lights, SATs for rectangular ones)"),
    intParam("max_aniso", 8, 1, 16,
             "mipmap taps along the longer axis of a rectangular light's kernel (anisotropy)"),
    intParam("mip_taps", 2, 1, 4,
             "mipmap taps per side of a square kernel (1 = the paper's single trilinear lookup)"),
    intParam("search_steps", 2, 0, 4,
             "blocker searches after the first, each over the cone cut at the last z_avg (0 = "
             "the paper's one search at the near plane)"),
    floatParam("ring_scale", 1.0, 0.5, 8.0,
               "ringing suppression: the filtered test is scaled by this about 1/2, then clamped"),
    floatParam("ring_shift", 0.08, 0.0, 0.5,
               "ringing suppression: the test is evaluated this far (normalised depth) nearer the "
               "light, so a surface does not shadow itself"),
    floatParam("sharpen_a", 30.0, 0.0, 1000.0,
               "contact sharpening strength A in v^p, p = 1 + A exp(-B (d - z_avg)); 0 = off"),
    floatParam("sharpen_b", 30.0, 0.0, 10000.0,
               "contact sharpening falloff B (per unit of normalised depth)"),
    floatParam("env_threshold", 0.1, 0.001, 0.999,
               "environment: fitting threshold t (enlarge while E_added / E_enlarged > t)"),
    intParam("env_lights", 30, 1, 1024, "environment: the most lights fitted (brightest first)"),
    enumParam("env_shape", "square", "square|rect", "environment: shape of the fitted lights"),
    intParam("env_face_size", 32, 4, 256, "environment: cube face resolution for the fitting"),
    stringParam("env_lights_file", "",
                "environment: lights from a `penumbra fit-lights` JSON (relative to the scene "
                "file) instead of fitting; empty = fit"),
};

struct CssSettings {
    int order = 4;
    int map_size = 256;
    enum class FilterChoice { Auto, Mipmap, Sat } filter = FilterChoice::Sat;
    int max_aniso = 8;
    int mip_taps = 2;
    int search_steps = 2;
    float ring_scale = 1.0f, ring_shift = 0.08f;
    float sharpen_a = 30.0f, sharpen_b = 30.0f;
};

CssSettings cssSettings(const Params& params);

// The prefilter for LIGHT: the chosen one, or with `auto` mipmaps for a square light and
// summed-area tables for a rectangular one.
CsmMaps::Filter filterFor(const CssSettings& settings, const scene::RectLight& light);

}  // namespace penumbra::techniques::css
