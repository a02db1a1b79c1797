// `adaptive`: light subdivision on a dyadic grid (corner samples shared between cells, optional
// jitter inside each sample's finest cell) and its weightings; see light_quadtree.h.
#include "renderer/techniques/adaptive/light_quadtree.h"

#include "renderer/techniques/jitter_hash.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace penumbra::techniques::adaptive {

LightQuadtree::LightQuadtree(int max_depth, bool linear, bool jitter, unsigned seed)
    : max_depth_(max_depth), n_(1 << max_depth), linear_(linear), jitter_(jitter), seed_(seed) {
    reset();
}

void LightQuadtree::reset() {
    samples_.clear();
    index_.clear();
    leaves_.clear();
    if (linear_) {
        root_ = {{0, 0}, {n_, 0}, 0};
        add({0, 0}, 0);
        add({n_, 0}, 0);
        leaves_.push_back(root_);
    } else {
        root_ = {{0, 0}, {n_, n_}, 0};
        add({0, 0}, 0);
        add({n_, 0}, 0);
        add({n_, n_}, 0);
        add({0, n_}, 0);
        leaves_.push_back(root_);
    }
}

int LightQuadtree::find(glm::ivec2 g) const {
    auto it = index_.find(static_cast<long long>(g.y) * (n_ + 1) + g.x);
    return it == index_.end() ? -1 : it->second;
}

int LightQuadtree::add(glm::ivec2 g, int depth) {
    if (int i = find(g); i >= 0) return i;
    const int i = static_cast<int>(samples_.size());
    const float inv = 1.0f / static_cast<float>(n_);
    // A 1D light's samples lie on its centre line.
    glm::vec2 uv(float(g.x) * inv, linear_ ? 0.5f : float(g.y) * inv);
    if (jitter_) {
        // Uniform in the dual cell [g - 1/2, g + 1/2] / N clipped to the light: the part of
        // the light the sample stands for (a sample on the light's edge weighs half a cell).
        // Clamping a point drawn in the whole cell instead put half of the edge samples on the
        // edge itself (a quarter of the corners on the corner), and the penumbra came out
        // darker or lighter by their bias (the corpus: receivers' median 0.0072 -> 0.0070).
        const float half = 0.5f * inv;
        auto within = [&](float centre, float r) {
            const float lo = std::max(centre - half, 0.0f), hi = std::min(centre + half, 1.0f);
            return lo + r * (hi - lo);
        };
        const unsigned x = unsigned(g.x), y = unsigned(g.y);
        uv.x = within(uv.x, hashToUnit(seed_, x, 2 * y));
        if (!linear_) uv.y = within(uv.y, hashToUnit(seed_, x, 2 * y + 1));
    }
    samples_.push_back({g, uv, depth});
    index_[static_cast<long long>(g.y) * (n_ + 1) + g.x] = i;
    return i;
}

std::vector<std::pair<int, int>> LightQuadtree::comparisons(const QuadtreeCell& c) const {
    if (linear_) return {{find(c.lo), find(c.hi)}};
    return {{find(c.lo), find(c.hi)}, {find({c.hi.x, c.lo.y}), find({c.lo.x, c.hi.y})}};
}

std::vector<glm::ivec2> LightQuadtree::splitPoints(const QuadtreeCell& c) const {
    const glm::ivec2 m = (c.lo + c.hi) / 2;
    if (linear_) return {{m.x, 0}};
    return {{m.x, c.lo.y}, {c.hi.x, m.y}, {m.x, c.hi.y}, {c.lo.x, m.y}, m};
}

int LightQuadtree::newSamples(const QuadtreeCell& c) const {
    int n = 0;
    for (auto g : splitPoints(c)) n += find(g) < 0;
    return n;
}

std::vector<QuadtreeCell> LightQuadtree::split(const QuadtreeCell& c) {
    for (auto g : splitPoints(c)) add(g, c.depth + 1);
    const glm::ivec2 m = (c.lo + c.hi) / 2;
    const int d = c.depth + 1;
    std::vector<QuadtreeCell> children;
    if (linear_)
        children = {{c.lo, {m.x, 0}, d}, {{m.x, 0}, c.hi, d}};
    else
        children = {{c.lo, m, d},
                    {{m.x, c.lo.y}, {c.hi.x, m.y}, d},
                    {m, c.hi, d},
                    {{c.lo.x, m.y}, {m.x, c.hi.y}, d}};
    std::erase_if(leaves_, [&](const QuadtreeCell& l) { return l.lo == c.lo && l.hi == c.hi; });
    leaves_.insert(leaves_.end(), children.begin(), children.end());
    return children;
}

std::vector<float> LightQuadtree::weights(Weighting weighting,
                                          std::span<const QuadtreeCell> leaves) const {
    std::vector<double> v(samples_.size(), 0.0);
    std::vector<bool> corner(samples_.size(), false);
    for (const auto& c : leaves) {
        const glm::ivec2 size = c.hi - c.lo;
        const auto corners = linear_ ? std::vector{c.lo, c.hi}
                                     : std::vector{c.lo, c.hi, glm::ivec2{c.hi.x, c.lo.y},
                                                   glm::ivec2{c.lo.x, c.hi.y}};
        const double share = linear_ ? 0.5 * size.x : 0.25 * double(size.x) * double(size.y);
        for (auto g : corners) {
            corner[size_t(find(g))] = true;
            if (weighting == Weighting::Area) v[size_t(find(g))] += share;
        }
    }
    if (weighting != Weighting::Area)
        for (size_t i = 0; i < samples_.size(); ++i) {
            const double per_axis = 1.0 / (std::ldexp(1.0, samples_[i].depth) + 1.0);
            const double w =
                weighting == Weighting::Equal ? 1.0 : (linear_ ? per_axis : per_axis * per_axis);
            v[i] = corner[i] ? w : 0.0;
        }
    double sum = 0;
    for (double x : v) sum += x;
    std::vector<float> w;
    for (double x : v) w.push_back(static_cast<float>(x / sum));
    return w;
}

}  // namespace penumbra::techniques::adaptive
