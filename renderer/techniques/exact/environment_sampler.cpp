// Environment importance sampling: see environment_sampler.h.
#include "renderer/techniques/exact/environment_sampler.h"

#include <algorithm>
#include <cmath>

#include "renderer/scene/cube_faces.h"

namespace penumbra::techniques::exact {
namespace {

constexpr double kPi = 3.14159265358979323846;

// The index of the first entry of the cumulative CDF[first, first + n) above TARGET.
int pick(const std::vector<double>& cdf, size_t first, int n, double target) {
    const auto begin = cdf.begin() + std::ptrdiff_t(first);
    const auto it = std::upper_bound(begin, begin + n, target);
    return std::min(int(it - begin), n - 1);
}

}  // namespace

EnvironmentSampler::EnvironmentSampler(const scene::Environment& env, int max_blocks_x)
    : image_(*env.image),
      intensity_(env.intensity),
      cos_r_(std::cos(float(env.rotation_y * kPi / 180.0))),
      sin_r_(std::sin(float(env.rotation_y * kPi / 180.0))),
      bx_(std::min(image_.width, max_blocks_x)),
      by_(std::min(image_.height, std::max(1, max_blocks_x / 2))) {
    rows_.resize(size_t(by_));
    columns_.resize(size_t(by_) * size_t(bx_));
    density_.resize(columns_.size());
    std::vector<double> energy(columns_.size(), 0.0);
    // Mean luminance of each block's texels.
    std::vector<int> count(energy.size(), 0);
    for (int y = 0; y < image_.height; ++y) {
        const int j = int((long(y) * by_) / image_.height);
        for (int x = 0; x < image_.width; ++x) {
            const int i = int((long(x) * bx_) / image_.width);
            const float* c = &image_.rgb[(size_t(y) * size_t(image_.width) + size_t(x)) * 3];
            energy[size_t(j) * size_t(bx_) + size_t(i)] +=
                0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2];
            ++count[size_t(j) * size_t(bx_) + size_t(i)];
        }
    }
    double row_sum = 0;
    for (int j = 0; j < by_; ++j) {
        // The band's solid angle per block: 2 pi / bx (cos theta0 - cos theta1).
        const double band =
            2.0 * kPi / bx_ * (std::cos(kPi * j / by_) - std::cos(kPi * (j + 1) / by_));
        double sum = 0;
        for (int i = 0; i < bx_; ++i) {
            const size_t b = size_t(j) * size_t(bx_) + size_t(i);
            energy[b] = count[b] > 0 ? energy[b] / count[b] * band : 0.0;
            columns_[b] = sum += energy[b];
        }
        rows_[size_t(j)] = row_sum += sum;
    }
    total_ = row_sum;
    for (int j = 0; j < by_; ++j) {
        const double band =
            2.0 * kPi / bx_ * (std::cos(kPi * j / by_) - std::cos(kPi * (j + 1) / by_));
        for (int i = 0; i < bx_; ++i) {
            const size_t b = size_t(j) * size_t(bx_) + size_t(i);
            density_[b] = total_ > 0 && band > 0 ? float(energy[b] / total_ / band) : 0.0f;
        }
    }
}

glm::vec3 EnvironmentSampler::sample(float u1, float u2) const {
    const int j = pick(rows_, 0, by_, u1 * total_);
    const double row_start = j > 0 ? rows_[size_t(j - 1)] : 0.0;
    const double row = rows_[size_t(j)] - row_start;
    // Reuse what is left of U1 inside the row's share for the column.
    const double f = row > 0 ? (u1 * total_ - row_start) / row : 0.5;
    const size_t base = size_t(j) * size_t(bx_);
    const int i = pick(columns_, base, bx_, f * columns_[base + size_t(bx_) - 1]);
    const double col_start = i > 0 ? columns_[base + size_t(i) - 1] : 0.0;
    const double col = columns_[base + size_t(i)] - col_start;
    const double g = col > 0 ? (f * columns_[base + size_t(bx_) - 1] - col_start) / col : 0.5;
    // Uniform in solid angle inside the block: u linear, cos theta linear.
    const double u = (i + std::clamp(g, 0.0, 1.0)) / bx_;
    const double c0 = std::cos(kPi * j / by_), c1 = std::cos(kPi * (j + 1) / by_);
    const double ct = c0 + (c1 - c0) * double(u2);
    const double v = std::acos(std::clamp(ct, -1.0, 1.0)) / kPi;
    return toWorld(scene::equirectDirection(float(u), float(v)));
}

float EnvironmentSampler::pdf(const glm::vec3& dir) const {
    const glm::vec2 uv = scene::equirectCoordinates(toMap(dir));
    const int i = std::clamp(int(uv.x * float(bx_)), 0, bx_ - 1);
    const int j = std::clamp(int(uv.y * float(by_)), 0, by_ - 1);
    return density_[size_t(j) * size_t(bx_) + size_t(i)];
}

glm::vec3 EnvironmentSampler::radiance(const glm::vec3& dir) const {
    const glm::vec2 uv = scene::equirectCoordinates(toMap(dir));
    const int x = std::clamp(int(uv.x * float(image_.width)), 0, image_.width - 1);
    const int y = std::clamp(int(uv.y * float(image_.height)), 0, image_.height - 1);
    const float* c = &image_.rgb[(size_t(y) * size_t(image_.width) + size_t(x)) * 3];
    return intensity_ * glm::vec3(c[0], c[1], c[2]);
}

// rotation_y turns the map about +y (as techniques/environment_lights.cpp's far lights do).
glm::vec3 EnvironmentSampler::toWorld(const glm::vec3& m) const {
    return {cos_r_ * m.x + sin_r_ * m.z, m.y, -sin_r_ * m.x + cos_r_ * m.z};
}
glm::vec3 EnvironmentSampler::toMap(const glm::vec3& w) const {
    return {cos_r_ * w.x - sin_r_ * w.z, w.y, sin_r_ * w.x + cos_r_ * w.z};
}

}  // namespace penumbra::techniques::exact
