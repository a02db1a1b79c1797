// `adaptive`: the CPU side of Schwärzler's light subdivision: sample points on a dyadic grid
// of the light, the quadtree (or 1D) cells whose corners they are, and the sample weights.
#pragma once

#include <array>
#include <span>
#include <unordered_map>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

namespace penumbra::techniques::adaptive {

struct QuadtreeSample {
    glm::ivec2 grid;  // position on the finest grid, (0..N)^2 with N = 2^max_depth
    glm::vec2 uv;     // position on the light in [0,1]^2
    int depth;        // subdivision depth at which the sample was created
};

// A cell of the subdivision: a square (2D light) or a segment (1D light, lo.y = hi.y = 0).
struct QuadtreeCell {
    glm::ivec2 lo, hi;
    int depth;
};

class LightQuadtree {
public:
    // MAX_DEPTH bounds the grid; LINEAR selects the 1D subdivision of a light with zero height.
    // With JITTER, each sample moves to a random point (seeded by SEED and its grid position) of
    // its finest-grid dual cell clipped to the light, so fully refined regions are stratified
    // rather than regular.
    LightQuadtree(int max_depth, bool linear, bool jitter = false, unsigned seed = 1);

    // Back to the initial samples (the light's corners or ends) and the single root cell.
    void reset();
    const std::vector<QuadtreeSample>& samples() const { return samples_; }
    const QuadtreeCell& root() const { return root_; }
    bool linear() const { return linear_; }

    // The sample pairs (indices) compared for CELL: its two diagonals (2D) or its ends (1D).
    std::vector<std::pair<int, int>> comparisons(const QuadtreeCell& cell) const;
    // How many new samples splitting CELL would create (shared ones exist already).
    int newSamples(const QuadtreeCell& cell) const;
    // Splits CELL, creating its missing corner samples at depth cell.depth + 1; returns the
    // children (4 in 2D, 2 in 1D).
    std::vector<QuadtreeCell> split(const QuadtreeCell& cell);

    // The cells never split: they tile the light.
    const std::vector<QuadtreeCell>& leaves() const { return leaves_; }

    // In the order of the `weights` parameter's choices (adaptive.cpp's kWeights).
    enum class Weighting {
        Area,   // each leaf's area shared by its corners: the integral of the bilinear
                // interpolant of the samples (a trapezoid rule on the adaptive grid)
        Paper,  // 1/(2^d+1)^2 (2D) or 1/(2^d+1) (1D) by creation depth d (eq. 5, 6)
        Equal,  // every sample alike
    };
    // Normalised weights of every sample, in sample order.
    std::vector<float> weights(Weighting weighting) const { return weights(weighting, leaves_); }
    // The same over the light's part LEAVES tile (cells of this tree): samples that are no
    // corner of theirs weigh 0.
    std::vector<float> weights(Weighting weighting, std::span<const QuadtreeCell> leaves) const;

private:
    int find(glm::ivec2 grid) const;
    int add(glm::ivec2 grid, int depth);
    std::vector<glm::ivec2> splitPoints(const QuadtreeCell& cell) const;

    int max_depth_;
    int n_;  // finest grid: 2^max_depth intervals per axis
    bool linear_;
    bool jitter_;
    unsigned seed_;
    QuadtreeCell root_{};
    std::vector<QuadtreeSample> samples_;
    std::vector<QuadtreeCell> leaves_;
    std::unordered_map<long long, int> index_;  // grid key -> sample index
};

}  // namespace penumbra::techniques::adaptive
