// Environment maps as cube faces: see cube_faces.h.
#include "renderer/scene/cube_faces.h"

#include <algorithm>
#include <cmath>

namespace penumbra::scene {
namespace {
constexpr double kPi = 3.14159265358979323846;

// Bilinear lookup of IMAGE at (u, v), wrapping in u and clamping in v.
glm::vec3 sampleEquirect(const EnvironmentImage& image, float u, float v) {
    const float x = u * static_cast<float>(image.width) - 0.5f;
    const float y = std::clamp(v * static_cast<float>(image.height) - 0.5f, 0.0f,
                               static_cast<float>(image.height - 1));
    const int x0 = static_cast<int>(std::floor(x)), y0 = static_cast<int>(std::floor(y));
    const float fx = x - static_cast<float>(x0), fy = y - static_cast<float>(y0);
    auto at = [&](int px, int py) {
        px = ((px % image.width) + image.width) % image.width;
        py = std::clamp(py, 0, image.height - 1);
        const size_t i =
            (static_cast<size_t>(py) * static_cast<size_t>(image.width) + static_cast<size_t>(px)) *
            3;
        return glm::vec3(image.rgb[i], image.rgb[i + 1], image.rgb[i + 2]);
    };
    return glm::mix(glm::mix(at(x0, y0), at(x0 + 1, y0), fx),
                    glm::mix(at(x0, y0 + 1), at(x0 + 1, y0 + 1), fx), fy);
}
}  // namespace

glm::vec3 equirectDirection(float u, float v) {
    const double theta = kPi * v, phi = 2.0 * kPi * (u - 0.5);
    return glm::vec3(static_cast<float>(std::sin(theta) * std::sin(phi)),
                     static_cast<float>(std::cos(theta)),
                     static_cast<float>(-std::sin(theta) * std::cos(phi)));
}

glm::vec2 equirectCoordinates(const glm::vec3& d) {
    const glm::vec3 n = glm::normalize(d);
    const double phi = std::atan2(n.x, -n.z);
    const double theta = std::acos(std::clamp(static_cast<double>(n.y), -1.0, 1.0));
    return {static_cast<float>(phi / (2.0 * kPi) + 0.5), static_cast<float>(theta / kPi)};
}

glm::vec3 cubeDirection(int face, float a, float b) {
    switch (face) {
        case 0:
            return {1.0f, -b, -a};
        case 1:
            return {-1.0f, -b, a};
        case 2:
            return {a, 1.0f, b};
        case 3:
            return {a, -1.0f, -b};
        case 4:
            return {a, -b, 1.0f};
        default:
            return {-a, -b, -1.0f};
    }
}

double cubeTexelSolidAngle(int n, int i, int j) {
    // The exact solid angle of the square [a0, a1] x [b0, b1] on the plane at distance 1:
    // F(a1, b1) - F(a0, b1) - F(a1, b0) + F(a0, b0), F(a, b) = atan(a b / sqrt(1 + a^2 + b^2)).
    auto f = [](double a, double b) { return std::atan2(a * b, std::sqrt(1.0 + a * a + b * b)); };
    const double step = 2.0 / n;
    const double a0 = -1.0 + i * step, a1 = a0 + step, b0 = -1.0 + j * step, b1 = b0 + step;
    return f(a1, b1) - f(a0, b1) - f(a1, b0) + f(a0, b0);
}

double CubeFaces::totalLuminance() const {
    double sum = 0;
    for (const auto& face : energy)
        for (const auto& e : face) sum += luminance(e);
    return sum;
}

CubeFaces toCubeFaces(const EnvironmentImage& image, int size, float intensity) {
    CubeFaces faces;
    faces.size = size;
    // Samples per texel side: a face texel spans about width / (4 size) map texels.
    const int samples = std::clamp((image.width + 4 * size - 1) / (4 * size), 1, 8);
    for (int f = 0; f < 6; ++f) {
        auto& out = faces.energy[static_cast<size_t>(f)];
        out.resize(static_cast<size_t>(size) * static_cast<size_t>(size));
        for (int j = 0; j < size; ++j)
            for (int i = 0; i < size; ++i) {
                glm::vec3 sum(0.0f);
                for (int sj = 0; sj < samples; ++sj)
                    for (int si = 0; si < samples; ++si) {
                        const float a = -1.0f + 2.0f *
                                                    (static_cast<float>(i) +
                                                     (static_cast<float>(si) + 0.5f) / samples) /
                                                    static_cast<float>(size);
                        const float b = -1.0f + 2.0f *
                                                    (static_cast<float>(j) +
                                                     (static_cast<float>(sj) + 0.5f) / samples) /
                                                    static_cast<float>(size);
                        const glm::vec2 uv = equirectCoordinates(cubeDirection(f, a, b));
                        sum += sampleEquirect(image, uv.x, uv.y);
                    }
                const float omega = static_cast<float>(cubeTexelSolidAngle(size, i, j));
                out[static_cast<size_t>(j * size + i)] =
                    sum * (intensity * omega / static_cast<float>(samples * samples));
            }
    }
    return faces;
}

}  // namespace penumbra::scene
