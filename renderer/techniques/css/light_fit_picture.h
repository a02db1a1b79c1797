// A picture of a light fit (like Figure 10 of Annen et al. 2008): the environment map,
// tone-mapped, with each fitted light's outline drawn on it, as 8-bit RGB.
#pragma once

#include <vector>

#include "renderer/scene/light_fitting.h"

namespace penumbra::techniques::css {

struct Picture {
    int width = 0, height = 0;
    std::vector<unsigned char> rgb;  // rows top to bottom
};

// IMAGE resampled to at most MAX_WIDTH wide (2:1), exposed so that its mean luminance shows
// as mid grey, with FIT's face rectangles outlined (mapped through the cube faces of SIZE).
Picture drawLightFit(const scene::EnvironmentImage& image, const scene::LightFit& fit,
                     int face_size, int max_width = 1024);

}  // namespace penumbra::techniques::css
