// `exact`: visibility by ray casting (Embree 3), the ground truth every other technique is
// measured against. Per pixel, N x N stratified jittered points on the light, one shadow ray
// each from the G-buffer position against the casters the rasteriser draws.
#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <thread>

#include "renderer/passes/readback.h"
#include "renderer/techniques/exact/environment_sampler.h"
#include "renderer/techniques/exact/ray_scene.h"
#include "renderer/techniques/jitter_hash.h"
#include "renderer/techniques/registry_entries.h"

namespace penumbra::techniques {
namespace {

constexpr std::array kExactParams = {
    intParam("samples", 16, 1, 64,
             "N: N x N stratified jittered points on the light per pixel, "
             "one shadow ray each"),
    boolParam("jitter", true, "jitter each point inside its stratum, per pixel (false: centres)"),
    intParam("seed", 1, 0, 1 << 30, "seed of the jitter"),
    intParam("threads", 0, 0, 256, "ray-casting threads (0: one per core)"),
    floatParam("ray_offset", 1e-5, 0.0, 1e-2,
               "a shadow ray starts this far from its point, as a share of the casters' "
               "bounding diagonal (skips the point's own surface; no shadow-map bias)"),
    intParam("env_samples", 256, 2, 4096,
             "environment: shadow rays per pixel, half toward directions drawn by the map's "
             "luminance, half by the cosine, combined by multiple importance sampling"),
};

using Clock = std::chrono::steady_clock;

class Exact final : public Technique {
public:
    explicit Exact(const Params& p)
        : n_(p.getInt("samples")),
          jitter_(p.getBool("jitter")),
          seed_(static_cast<std::uint32_t>(p.getInt("seed"))),
          offset_(static_cast<float>(p.getFloat("ray_offset"))),
          env_samples_(p.getInt("env_samples")) {
        const int t = p.getInt("threads");
        threads_ = t > 0 ? t : int(std::max(1u, std::thread::hardware_concurrency()));
    }

    void prepare(const gl::ContextInfo&, const passes::GpuScene&) override {}

    void render(frame::FrameContext& ctx) override {
        const int w = ctx.gbuffer.width(), h = ctx.gbuffer.height();
        ctx.pass("exact_setup", [&] {
            rays_.update(ctx.scene);
            // The G-buffer is the frame's: read it once, for its first light.
            if (ctx.light == 0 || position_.empty()) {
                position_ = passes::readTexture(ctx.gbuffer.position(), w, h, 4, GL_RGBA);
                normal_ = passes::readTexture(ctx.gbuffer.normal(), w, h, 4, GL_RGBA);
            }
        });
        std::vector<float> out(size_t(w) * size_t(h) * 4);
        const auto start = Clock::now();
        std::uint64_t rays = 0;
        if (ctx.environmentLayer()) {
            // Built each frame (one pass over the map): the environment may be animated.
            environment_ = std::make_unique<exact::EnvironmentSampler>(*ctx.scene.environment);
            ctx.pass("exact_env_rays", [&] {
                rays = parallelRows(ctx, h, start, [&](size_t pix, float tnear) {
                    return traceEnvironment(pix, tnear, out);
                });
            });
        } else {
            const auto& l = ctx.currentLight();
            const auto c = l.corners();
            const Light light{c[0], c[1] - c[0], c[3] - c[0], l.forward()};
            ctx.pass("exact_rays", [&] {
                rays = parallelRows(ctx, h, start, [&](size_t pix, float tnear) {
                    return tracePixel(light, n_, pix, tnear, out);
                });
            });
        }
        const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
        ctx.pass("exact_upload", [&] { ctx.uploadVisibility(out); });
        auto& st = ctx.stats;
        const double total = st.value("rays_cast", 0.0) + double(rays);
        const double time = st.value("ray_seconds", 0.0) + seconds;
        st["rays_cast"] = total;
        st["ray_seconds"] = time;
        st["rays_per_second"] = time > 0 ? total / time : 0.0;
        st["threads"] = threads_;
        st["triangles"] = rays_.triangles();
    }

private:
    struct Light {
        glm::vec3 corner, edge_x, edge_y, forward;
    };

    // Runs PIXEL(index, tnear) -> rays cast for every pixel on threads_ threads, rows handed
    // out in chunks; the calling thread also reports progress. Returns the rays cast.
    template <class Pixel>
    std::uint64_t parallelRows(frame::FrameContext& ctx, int h, Clock::time_point start,
                               const Pixel& pixel) {
        const int w = ctx.gbuffer.width();
        const float tnear = offset_ * std::max(rays_.extent(), 1e-6f);
        constexpr int kRows = 4;
        std::atomic<int> next{0}, rows_done{0};
        std::atomic<std::uint64_t> rays{0};
        auto work = [&](bool report) {
            std::uint64_t mine = 0;
            for (;;) {
                const int y0 = next.fetch_add(kRows);
                if (y0 >= h) break;
                const int y1 = std::min(h, y0 + kRows);
                for (int y = y0; y < y1; ++y)
                    for (int x = 0; x < w; ++x)
                        mine += pixel(size_t(y) * size_t(w) + size_t(x), tnear);
                const int done = rows_done.fetch_add(y1 - y0) + (y1 - y0);
                if (report) reportProgress(ctx, done, h, rays + mine, start);
            }
            rays += mine;
        };
        std::vector<std::thread> pool;
        for (int t = 1; t < threads_; ++t) pool.emplace_back(work, false);
        work(true);
        for (auto& t : pool) t.join();
        return rays;
    }

    void reportProgress(frame::FrameContext& ctx, int done, int h, std::uint64_t rays,
                        Clock::time_point start) {
        const auto now = Clock::now();
        if (now - last_report_ < std::chrono::milliseconds(250)) return;
        last_report_ = now;
        const double s = std::chrono::duration<double>(now - start).count();
        const double share = double(done) / double(h);
        // The reporting thread's rays only until the others join: scale by the thread count.
        const double rate = s > 0 ? double(rays) * threads_ / s : 0.0;
        char line[96];
        std::snprintf(line, sizeof line, "exact %3.0f%% %.1f Mrays/s ETA %.0fs", 100 * share,
                      rate * 1e-6, share > 0 ? s * (1 - share) / share : 0.0);
        ctx.progress(line);
    }

    // One pixel's rays: OUT gets (unblocked share, sum c lit, sum c, 1), c = cos cos / r^2 of
    // the sample (0 below the receiver's horizon and behind the light). Returns rays cast.
    std::uint64_t tracePixel(const Light& light, int n, size_t pix, float tnear,
                             std::vector<float>& out) const {
        float* o = &out[4 * pix];
        if (position_[4 * pix + 3] == 0.0f) {  // background
            o[0] = 1, o[1] = 0, o[2] = 0, o[3] = 0;
            return 0;
        }
        const glm::vec3 p = position(pix), nrm = normal(pix);
        const auto pixel = static_cast<std::uint32_t>(pix);
        int lit = 0;
        double weighted = 0, weights = 0;
        std::array<glm::vec3, 8> dirs;
        std::array<float, 8> contrib;
        std::array<bool, 8> active, hit;
        const int total = n * n;
        for (int base = 0; base < total; base += 8) {
            for (int k = 0; k < 8; ++k) {
                const int s = base + k;
                active[size_t(k)] = s < total;
                if (s >= total) continue;
                const int i = s % n, j = s / n;
                const float jx = jitter_ ? hashToUnit(seed_, pixel, std::uint32_t(2 * s)) : 0.5f;
                const float jy =
                    jitter_ ? hashToUnit(seed_, pixel, std::uint32_t(2 * s + 1)) : 0.5f;
                const glm::vec3 q = light.corner + light.edge_x * ((float(i) + jx) / float(n)) +
                                    light.edge_y * ((float(j) + jy) / float(n));
                const glm::vec3 d = q - p;
                const float d2 = glm::dot(d, d);
                dirs[size_t(k)] = d;
                contrib[size_t(k)] = std::max(glm::dot(nrm, d), 0.0f) *
                                     std::max(-glm::dot(light.forward, d), 0.0f) /
                                     std::max(d2 * d2, 1e-30f);
            }
            rays_.occluded8(p, dirs.data(), active.data(), tnear, hit.data());
            for (int k = 0; k < 8; ++k) {
                if (!active[size_t(k)]) continue;
                const bool unblocked = !hit[size_t(k)];
                lit += unblocked;
                weights += contrib[size_t(k)];
                if (unblocked) weighted += contrib[size_t(k)];
            }
        }
        o[0] = float(lit) / float(total);
        o[1] = float(weighted / total);
        o[2] = float(weights / total);
        o[3] = 1;  // the light was sampled (glsl/passes/shading.glsl)
        return std::uint64_t(total);
    }

    glm::vec3 position(size_t pix) const {
        return {position_[4 * pix], position_[4 * pix + 1], position_[4 * pix + 2]};
    }
    // The G-buffer normal of PIX, unit length (+y where the G-buffer holds none).
    glm::vec3 normal(size_t pix) const {
        const glm::vec3 n(normal_[4 * pix], normal_[4 * pix + 1], normal_[4 * pix + 2]);
        const float len = glm::length(n);
        return len > 0 ? n / len : glm::vec3(0, 1, 0);
    }

    // The environment at one pixel: OUT gets (shadowed irradiance rgb, unshadowed luminance
    // irradiance), estimated from env_samples_ rays, half drawn by the map's luminance and
    // half by the cosine about the normal, weighted by the balance heuristic:
    // E = sum_k L cos / (n_l p_l + n_c p_c) over both sets. Returns rays cast.
    std::uint64_t traceEnvironment(size_t pix, float tnear, std::vector<float>& out) const {
        float* o = &out[4 * pix];
        o[0] = o[1] = o[2] = o[3] = 0;
        if (position_[4 * pix + 3] == 0.0f || environment_->empty()) return 0;
        const glm::vec3 p = position(pix), nrm = normal(pix);
        // An orthonormal frame about the normal for the cosine samples.
        const glm::vec3 helper = std::fabs(nrm.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
        const glm::vec3 tx = glm::normalize(glm::cross(helper, nrm)), ty = glm::cross(nrm, tx);
        const int half = env_samples_ / 2;
        const float n_l = float(half), n_c = float(env_samples_ - half);
        const float reach = rays_.reach(p);
        const auto pixel = static_cast<std::uint32_t>(pix);
        const std::uint32_t seed = seed_ ^ 0x5bd1e995u;  // another stream than the lights'
        glm::dvec3 shadowed(0.0), open(0.0);
        std::array<glm::vec3, 8> dirs{}, value{};  // value: L cos / (n_l p_l + n_c p_c)
        std::array<bool, 8> active{}, hit{};
        for (int base = 0; base < env_samples_; base += 8) {
            for (int k = 0; k < 8; ++k) {
                const int s = base + k;
                active[size_t(k)] = false;
                if (s >= env_samples_) continue;
                // Stratified per strategy: sample s of its set lies in stratum s of u1.
                const bool by_map = s < half;
                const int index = by_map ? s : s - half;
                const int count = by_map ? half : env_samples_ - half;
                const float u1 =
                    (float(index) + hashToUnit(seed, pixel, std::uint32_t(2 * s))) / float(count);
                const float u2 = hashToUnit(seed, pixel, std::uint32_t(2 * s + 1));
                glm::vec3 d;
                if (by_map) {
                    d = environment_->sample(std::min(u1, 0.99999994f), u2);
                } else {
                    const float r = std::sqrt(u1), phi = 2.0f * float(M_PI) * u2;
                    d = tx * (r * std::cos(phi)) + ty * (r * std::sin(phi)) +
                        nrm * std::sqrt(std::max(0.0f, 1.0f - u1));
                }
                const float cosine = glm::dot(nrm, d);
                if (!(cosine > 0.0f)) continue;  // below the horizon: adds nothing
                const float denom = n_l * environment_->pdf(d) + n_c * cosine / float(M_PI);
                if (!(denom > 0.0f)) continue;
                value[size_t(k)] = environment_->radiance(d) * (cosine / denom);
                dirs[size_t(k)] = d * reach;
                active[size_t(k)] = true;
            }
            rays_.occluded8(p, dirs.data(), active.data(), tnear, hit.data());
            for (int k = 0; k < 8; ++k) {
                if (!active[size_t(k)]) continue;
                open += glm::dvec3(value[size_t(k)]);
                if (!hit[size_t(k)]) shadowed += glm::dvec3(value[size_t(k)]);
            }
        }
        o[0] = float(shadowed.r), o[1] = float(shadowed.g), o[2] = float(shadowed.b);
        o[3] = float(0.2126 * open.r + 0.7152 * open.g + 0.0722 * open.b);
        return std::uint64_t(env_samples_);
    }

    int n_;
    bool jitter_;
    std::uint32_t seed_;
    float offset_;
    int env_samples_;
    std::unique_ptr<exact::EnvironmentSampler> environment_;
    int threads_ = 1;
    exact::RayScene rays_;
    std::vector<float> position_, normal_;
    Clock::time_point last_report_{};
};

}  // namespace

const TechniqueInfo kExactTechnique = {
    "exact",
    "ray-traced visibility (Embree): N x N stratified jittered shadow rays per pixel, the "
    "ground truth",
    kExactParams,
    [](const Params& p) -> std::unique_ptr<Technique> { return std::make_unique<Exact>(p); },
    // The environment is integrated per pixel (Exact::traceEnvironment): one irradiance layer.
    [](const Params&, const scene::Scene&) {
        EnvironmentLights env;
        env.irradiance_layer = true;
        return env;
    }};

}  // namespace penumbra::techniques
