// Greedy area-light fitting of environment maps: see light_fitting.h.
#include "renderer/scene/light_fitting.h"

#include <algorithm>
#include <cmath>

#include "renderer/core/error.h"

namespace penumbra::scene {
namespace {

struct Rect {
    int x0, y0, x1, y1;
};

// Per-face working state: residual luminance energy and RGB energy, and coverage.
struct Face {
    int n = 0;
    std::vector<double> lum;
    std::vector<glm::dvec3> rgb;
    std::vector<char> covered;
    double mean = 0;  // mean texel luminance energy of the original face
    double sum(const Rect& r) const {
        double s = 0;
        for (int y = r.y0; y < r.y1; ++y)
            for (int x = r.x0; x < r.x1; ++x) s += lum[size_t(y * n + x)];
        return s;
    }
};

// Grows R on FACE while an enlargement adds more than T of the enlarged energy: one side at
// a time for rectangles, one corner direction (both sides at once) for squares.
void grow(const Face& f, Rect& r, double t, bool square) {
    double energy = f.sum(r);
    for (bool changed = true; changed;) {
        changed = false;
        if (square) {
            Rect best = r;
            double best_added = -1;
            for (int dx : {-1, 1})
                for (int dy : {-1, 1}) {
                    Rect c{r.x0 - (dx < 0), r.y0 - (dy < 0), r.x1 + (dx > 0), r.y1 + (dy > 0)};
                    if (c.x0 < 0 || c.y0 < 0 || c.x1 > f.n || c.y1 > f.n) continue;
                    const double added = f.sum(c) - energy;
                    if (added > best_added) best_added = added, best = c;
                }
            if (best_added >= 0 && best_added / (energy + best_added) > t) {
                r = best, energy += best_added, changed = true;
            }
            continue;
        }
        const Rect sides[4] = {{r.x0 - 1, r.y0, r.x1, r.y1},
                               {r.x0, r.y0, r.x1 + 1, r.y1},
                               {r.x0, r.y0 - 1, r.x1, r.y1},
                               {r.x0, r.y0, r.x1, r.y1 + 1}};
        for (const Rect& c : sides) {
            if (c.x0 < 0 || c.y0 < 0 || c.x1 > f.n || c.y1 > f.n) continue;
            const double added = f.sum(c) - energy;
            if (added / (energy + added) > t) r = c, energy += added, changed = true;
        }
    }
}

// Direction, axes, extent and solid angle of rectangle R of face FACE (N x N).
void describe(FittedLight& l, int face, int n, const Rect& r) {
    const auto coord = [n](int i) { return -1.0f + 2.0f * static_cast<float>(i) / n; };
    const float a0 = coord(r.x0), a1 = coord(r.x1), b0 = coord(r.y0), b1 = coord(r.y1);
    const glm::vec3 centre = cubeDirection(face, 0.5f * (a0 + a1), 0.5f * (b0 + b1));
    l.direction = glm::normalize(centre);
    // The face's up axis (-b) made perpendicular to the direction; right as a rect light facing
    // the scene (forward = -direction) computes it, so extent.x lies along the face's a axis.
    const glm::vec3 db = cubeDirection(face, 0.0f, -1.0f) - cubeDirection(face, 0.0f, 0.0f);
    l.up = glm::normalize(db - glm::dot(db, l.direction) * l.direction);
    l.right = glm::normalize(glm::cross(-l.direction, l.up));
    const float dist = glm::length(centre);
    l.extent = {2.0f * std::atan(0.5f * (a1 - a0) / dist),
                2.0f * std::atan(0.5f * (b1 - b0) / dist)};
    l.solid_angle = 0;
    for (int y = r.y0; y < r.y1; ++y)
        for (int x = r.x0; x < r.x1; ++x) l.solid_angle += cubeTexelSolidAngle(n, x, y);
    l.face = face, l.x0 = r.x0, l.y0 = r.y0, l.x1 = r.x1, l.y1 = r.y1;
}

}  // namespace

LightFit fitLights(const CubeFaces& faces, const FitSettings& s) {
    const int n = faces.size;
    std::vector<Face> fs(6);
    LightFit fit;
    for (int f = 0; f < 6; ++f) {
        Face& face = fs[size_t(f)];
        face.n = n;
        for (const auto& e : faces.energy[size_t(f)]) {
            face.lum.push_back(luminance(e));
            face.rgb.emplace_back(e);
        }
        face.covered.assign(face.lum.size(), 0);
        double sum = 0;
        for (double v : face.lum) sum += v;
        face.mean = face.lum.empty() ? 0 : sum / static_cast<double>(face.lum.size());
        fit.total += sum;
    }
    double captured = 0;
    while (s.max_lights <= 0 || static_cast<int>(fit.lights.size()) < s.max_lights) {
        // The brightest uncovered texel over all faces.
        int best_face = -1;
        size_t best = 0;
        double best_lum = 0;
        for (int f = 0; f < 6; ++f)
            for (size_t i = 0; i < fs[size_t(f)].lum.size(); ++i)
                if (!fs[size_t(f)].covered[i] && (best_face < 0 || fs[size_t(f)].lum[i] > best_lum))
                    best_face = f, best = i, best_lum = fs[size_t(f)].lum[i];
        if (best_face < 0 || best_lum <= 0) break;  // covered, or only black texels left
        Face& face = fs[size_t(best_face)];
        Rect r{int(best) % n, int(best) / n, int(best) % n + 1, int(best) / n + 1};
        grow(face, r, s.threshold, s.square);
        FittedLight light;
        describe(light, best_face, n, r);
        glm::dvec3 taken(0.0);
        double taken_lum = 0;
        for (int y = r.y0; y < r.y1; ++y)
            for (int x = r.x0; x < r.x1; ++x) {
                const size_t i = size_t(y * n + x);
                const double keep = std::min(face.lum[i], s.residual * face.mean);
                const double part = face.lum[i] > 0 ? 1.0 - keep / face.lum[i] : 0.0;
                taken += face.rgb[i] * part;
                taken_lum += face.lum[i] - keep;
                face.rgb[i] *= 1.0 - part;
                face.lum[i] = keep;
                face.covered[i] = 1;
            }
        light.energy = glm::vec3(taken);
        light.share = fit.total > 0 ? taken_lum / fit.total : 0;
        captured += taken_lum;
        fit.lights.push_back(light);
    }
    fit.captured = fit.total > 0 ? captured / fit.total : 0;
    return fit;
}

}  // namespace penumbra::scene
