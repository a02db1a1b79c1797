// A picture of a light fit: see light_fit_picture.h.
#include "renderer/techniques/css/light_fit_picture.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "renderer/output/tone_map.h"

namespace penumbra::techniques::css {

using scene::cubeDirection;
using scene::equirectCoordinates;
using scene::FittedLight;
using scene::luminance;

Picture drawLightFit(const scene::EnvironmentImage& image, const scene::LightFit& fit,
                     int face_size, int max_width) {
    Picture p;
    p.width = std::min(image.width, max_width);
    p.height = std::max(p.width / 2, 1);
    p.rgb.assign(static_cast<size_t>(p.width * p.height) * 3, 0);
    double mean = 0;
    for (size_t i = 0; i + 2 < image.rgb.size(); i += 3)
        mean += luminance({image.rgb[i], image.rgb[i + 1], image.rgb[i + 2]});
    mean /= std::max<double>(1.0, double(image.rgb.size() / 3));
    const float exposure = mean > 0 ? static_cast<float>(std::log2(0.18 / mean)) : 0.0f;
    for (int y = 0; y < p.height; ++y)
        for (int x = 0; x < p.width; ++x) {
            const int sx = x * image.width / p.width, sy = y * image.height / p.height;
            const size_t s = (static_cast<size_t>(sy) * size_t(image.width) + size_t(sx)) * 3;
            const size_t d = (static_cast<size_t>(y) * size_t(p.width) + size_t(x)) * 3;
            for (int c = 0; c < 3; ++c)
                p.rgb[d + size_t(c)] = output::toneMap8(image.rgb[s + size_t(c)], exposure);
        }
    static constexpr std::array<std::array<unsigned char, 3>, 4> kColours = {
        {{255, 40, 40}, {255, 220, 0}, {40, 220, 255}, {80, 255, 80}}};
    auto plot = [&](const glm::vec3& dir, const std::array<unsigned char, 3>& colour) {
        const glm::vec2 uv = equirectCoordinates(dir);
        const int x = std::clamp(static_cast<int>(uv.x * float(p.width)), 0, p.width - 1);
        const int y = std::clamp(static_cast<int>(uv.y * float(p.height)), 0, p.height - 1);
        const size_t d = (static_cast<size_t>(y) * size_t(p.width) + size_t(x)) * 3;
        for (int c = 0; c < 3; ++c) p.rgb[d + size_t(c)] = colour[size_t(c)];
    };
    const auto coord = [face_size](float i) { return -1.0f + 2.0f * i / float(face_size); };
    const int steps = 4 * std::max(p.width / face_size, 4);
    for (size_t k = 0; k < fit.lights.size(); ++k) {
        const FittedLight& l = fit.lights[k];
        const auto& colour = kColours[k % kColours.size()];
        const float a0 = coord(float(l.x0)), a1 = coord(float(l.x1));
        const float b0 = coord(float(l.y0)), b1 = coord(float(l.y1));
        for (int i = 0; i <= steps; ++i) {
            const float t = float(i) / float(steps);
            const float a = a0 + (a1 - a0) * t, b = b0 + (b1 - b0) * t;
            plot(cubeDirection(l.face, a, b0), colour);
            plot(cubeDirection(l.face, a, b1), colour);
            plot(cubeDirection(l.face, a0, b), colour);
            plot(cubeDirection(l.face, a1, b), colour);
        }
    }
    return p;
}

}  // namespace penumbra::techniques::css
