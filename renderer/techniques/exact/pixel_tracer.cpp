// One pixel's shadow rays for `exact`: toward stratified jittered points of a rect light, or
// toward the environment by multiple importance sampling (see pixel_tracer.h).
#include "renderer/techniques/exact/pixel_tracer.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "renderer/techniques/jitter_hash.h"

namespace penumbra::techniques::exact {

// One pixel's rays: OUT gets (unblocked share, sum c lit, sum c, 1), c = cos cos / r^2 of
// the sample (0 below the receiver's horizon and behind the light); a sample beyond the facet
// of a surface that casts is blocked by that surface without a ray. Returns rays cast.
std::uint64_t PixelTracer::tracePixel(const AreaLight& light, int n, size_t pix, float tnear,
                                      std::vector<float>& out) const {
    float* o = &out[4 * pix];
    if (position[4 * pix + 3] == 0.0f) {  // background
        o[0] = 1, o[1] = 0, o[2] = 0, o[3] = 0;
        return 0;
    }
    const glm::vec3 p = positionAt(pix), nrm = normalAt(pix), ng = facetAt(pix);
    tnear = nearFrom(p, tnear);
    const auto pixel = static_cast<std::uint32_t>(pix);
    int lit = 0;
    double weighted = 0, weights = 0;
    std::array<glm::vec3, 8> origins{}, dirs{};  // inactive lanes stay zero
    std::array<float, 8> contrib;
    std::array<bool, 8> active, hit;
    const int total = n * n;
    std::uint64_t cast = 0;
    for (int base = 0; base < total; base += 8) {
        for (int k = 0; k < 8; ++k) {
            const int s = base + k;
            active[size_t(k)] = s < total;
            if (s >= total) continue;
            const int i = s % n, j = s / n;
            const float jx = jitter ? hashToUnit(seed, pixel, std::uint32_t(2 * s)) : 0.5f;
            const float jy = jitter ? hashToUnit(seed, pixel, std::uint32_t(2 * s + 1)) : 0.5f;
            const glm::vec3 q = light.corner + light.edge_x * ((float(i) + jx) / float(n)) +
                                light.edge_y * ((float(j) + jy) / float(n));
            const glm::vec3 d = q - p;
            const float d2 = glm::dot(d, d);
            active[size_t(k)] = !throughOwnSurface(pix, ng, d);  // else blocked, no ray
            cast += active[size_t(k)];
            origins[size_t(k)] = origin(p, ng, d, tnear);
            dirs[size_t(k)] = q - origins[size_t(k)];
            contrib[size_t(k)] = std::max(glm::dot(nrm, d), 0.0f) *
                                 std::max(-glm::dot(light.forward, d), 0.0f) /
                                 std::max(d2 * d2, 1e-30f);
        }
        rays.occluded8(origins.data(), dirs.data(), active.data(), tnear, hit.data());
        for (int k = 0; k < 8 && base + k < total; ++k) {
            const bool unblocked = active[size_t(k)] && !hit[size_t(k)];
            lit += unblocked;
            weights += contrib[size_t(k)];
            if (unblocked) weighted += contrib[size_t(k)];
        }
    }
    o[0] = float(lit) / float(total);
    o[1] = float(weighted / total);
    o[2] = float(weights / total);
    o[3] = 1;  // the light was sampled (glsl/passes/shading.glsl)
    return cast;
}

glm::vec3 PixelTracer::positionAt(size_t pix) const {
    return {position[4 * pix], position[4 * pix + 1], position[4 * pix + 2]};
}
// The G-buffer normal of PIX, unit length (+y where the G-buffer holds none).
namespace {
// The RGBA buffer's xyz at PIX, unit length (NONE where it is zero).
glm::vec3 unitAt(const std::vector<float>& rgba, size_t pix, const glm::vec3& none) {
    const glm::vec3 n(rgba[4 * pix], rgba[4 * pix + 1], rgba[4 * pix + 2]);
    const float len = glm::length(n);
    return len > 0 ? n / len : none;
}
}  // namespace

glm::vec3 PixelTracer::normalAt(size_t pix) const {
    return unitAt(normal, pix, glm::vec3(0, 1, 0));
}
glm::vec3 PixelTracer::facetAt(size_t pix) const {
    return unitAt(geometric, pix, glm::vec3(0));
}
bool PixelTracer::throughOwnSurface(size_t pix, const glm::vec3& ng, const glm::vec3& d) const {
    return casts[pix] != 0 && ng != glm::vec3(0.0f) && glm::dot(ng, d) <= 0.0f;
}
float PixelTracer::nearFrom(const glm::vec3& p, float tnear) {
    // 8 float steps (2^-20) of P's largest coordinate: 1000 m from the origin a step is 1.2e-4 m,
    // more than the casters' share (1e-5 of a fence's 5 m), and the posts were speckled by their
    // own surfaces (fence 1000 m away: mean |visibility difference| to the scene at the origin
    // 0.0089, 8e-5 with 4 steps, 1.2e-4 with 8; 10 km away 0.0010, `reference` there 0.0008).
    const float m = std::max({std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)});
    return std::max(tnear, m * 0x1p-20f);
}
glm::vec3 PixelTracer::origin(const glm::vec3& p, const glm::vec3& ng, const glm::vec3& d,
                              float near) {
    return glm::dot(ng, d) > 0.0f ? p + ng * near : p;
}

// The environment at one pixel: OUT gets (shadowed irradiance rgb, unshadowed luminance
// irradiance), estimated from env_samples rays, half drawn by the map's luminance and
// half by the cosine about the normal, weighted by the balance heuristic:
// E = sum_k L cos / (n_l p_l + n_c p_c) over both sets. Returns rays cast.
std::uint64_t PixelTracer::traceEnvironment(size_t pix, float tnear,
                                            std::vector<float>& out) const {
    float* o = &out[4 * pix];
    o[0] = o[1] = o[2] = o[3] = 0;
    if (position[4 * pix + 3] == 0.0f || environment->empty()) return 0;
    const glm::vec3 p = positionAt(pix), nrm = normalAt(pix), ng = facetAt(pix);
    tnear = nearFrom(p, tnear);
    // An orthonormal frame about the normal for the cosine samples.
    const glm::vec3 helper = std::fabs(nrm.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
    const glm::vec3 tx = glm::normalize(glm::cross(helper, nrm)), ty = glm::cross(nrm, tx);
    const int half = env_samples / 2;
    const float n_l = float(half), n_c = float(env_samples - half);
    const float reach = rays.reach(p);
    const auto pixel = static_cast<std::uint32_t>(pix);
    const std::uint32_t env_seed = seed ^ 0x5bd1e995u;  // another stream than the lights'
    glm::dvec3 shadowed(0.0), open(0.0);
    std::array<glm::vec3, 8> origins{}, dirs{}, value{};  // value: L cos / (n_l p_l + n_c p_c)
    std::array<bool, 8> active{}, hit{};
    std::uint64_t cast = 0;
    for (int base = 0; base < env_samples; base += 8) {
        for (int k = 0; k < 8; ++k) {
            const int s = base + k;
            active[size_t(k)] = false;
            if (s >= env_samples) continue;
            // Stratified per strategy: sample s of its set lies in stratum s of u1.
            const bool by_map = s < half;
            const int index = by_map ? s : s - half;
            const int count = by_map ? half : env_samples - half;
            const float u1 =
                (float(index) + hashToUnit(env_seed, pixel, std::uint32_t(2 * s))) / float(count);
            const float u2 = hashToUnit(env_seed, pixel, std::uint32_t(2 * s + 1));
            glm::vec3 d;
            if (by_map) {
                d = environment->sample(std::min(u1, 0.99999994f), u2);
            } else {
                const float r = std::sqrt(u1), phi = 2.0f * float(M_PI) * u2;
                d = tx * (r * std::cos(phi)) + ty * (r * std::sin(phi)) +
                    nrm * std::sqrt(std::max(0.0f, 1.0f - u1));
            }
            const float cosine = glm::dot(nrm, d);
            if (!(cosine > 0.0f)) continue;  // below the horizon: adds nothing
            const float denom = n_l * environment->pdf(d) + n_c * cosine / float(M_PI);
            if (!(denom > 0.0f)) continue;
            value[size_t(k)] = environment->radiance(d) * (cosine / denom);
            open += glm::dvec3(value[size_t(k)]);
            if (throughOwnSurface(pix, ng, d)) continue;  // blocked: no ray
            origins[size_t(k)] = origin(p, ng, d, tnear);
            dirs[size_t(k)] = d * reach;
            active[size_t(k)] = true;
            ++cast;
        }
        rays.occluded8(origins.data(), dirs.data(), active.data(), tnear, hit.data());
        for (int k = 0; k < 8; ++k) {
            if (active[size_t(k)] && !hit[size_t(k)]) shadowed += glm::dvec3(value[size_t(k)]);
        }
    }
    o[0] = float(shadowed.r), o[1] = float(shadowed.g), o[2] = float(shadowed.b);
    o[3] = float(0.2126 * open.r + 0.7152 * open.g + 0.0722 * open.b);
    return cast;
}

}  // namespace penumbra::techniques::exact
