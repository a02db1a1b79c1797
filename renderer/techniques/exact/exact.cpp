// `exact`: visibility by ray casting (Embree 3), the ground truth every other technique is
// measured against. Per pixel, N x N stratified jittered points on the light, one shadow ray
// each from the G-buffer position against the casters the rasteriser draws (pixel_tracer.h);
// here the technique, its parameters and the threads that share the rows.
#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <thread>

#include "renderer/core/memory_limit.h"
#include "renderer/passes/readback.h"
#include "renderer/techniques/exact/environment_sampler.h"
#include "renderer/techniques/exact/pixel_tracer.h"
#include "renderer/techniques/exact/ray_scene.h"
#include "renderer/techniques/param_keys.h"
#include "renderer/techniques/registry_entries.h"

namespace penumbra::techniques {
namespace {

constexpr IntKey kThreads{"threads"};
constexpr FloatKey kRayOffset{"ray_offset"};

constexpr std::array kExactParams = {
    intParam(kSamples, 16, 1, 64,
             "N: N x N stratified jittered points on the light per pixel, "
             "one shadow ray each"),
    boolParam(kJitter, true, "jitter each point inside its stratum, per pixel (false: centres)"),
    intParam(kSeed, 1, 0, 1 << 30, "seed of the jitter"),
    intParam(kThreads, 0, 0, 256, "ray-casting threads (0: one per core)"),
    floatParam(kRayOffset, 1e-5, 0.0, 1e-2,
               "a shadow ray skips this much of its start and, toward light above the "
               "point's facet, starts this far off it; a share of the casters' bounding "
               "diagonal, at least 8 float steps of the point's coordinates (skips the "
               "point's own surface; no shadow-map bias)"),
    intParam(kEnvSamples, 256, 2, 4096,
             "environment: shadow rays per pixel, half toward directions drawn by the map's "
             "luminance, half by the cosine, combined by multiple importance sampling"),
};

using Clock = std::chrono::steady_clock;

class Exact final : public Technique {
public:
    explicit Exact(const Params& p)
        : n_(p.get(kSamples)),
          jitter_(p.get(kJitter)),
          seed_(static_cast<std::uint32_t>(p.get(kSeed))),
          offset_(static_cast<float>(p.get(kRayOffset))),
          env_samples_(p.get(kEnvSamples)) {
        const int t = p.get(kThreads);
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
                geometric_ = passes::readTexture(ctx.gbuffer.geometricNormal(), w, h, 4, GL_RGBA);
                const std::vector<float> ids =
                    passes::readTexture(ctx.gbuffer.id(), w, h, 1, GL_RED_INTEGER);
                casts_.assign(ids.size(), 0);
                const auto& objects = ctx.scene.objects;
                for (size_t i = 0; i < ids.size(); ++i) {
                    const auto id = static_cast<long>(ids[i]);
                    casts_[i] = id >= 0 && size_t(id) < objects.size() &&
                                scene::castsShadow(objects[size_t(id)].shadow);
                }
            }
        });
        std::vector<float> out(size_t(w) * size_t(h) * 4);
        const auto start = Clock::now();
        std::uint64_t rays = 0;
        if (ctx.environmentLayer()) {
            // Built each frame (one pass over the map): the environment may be animated.
            environment_ = std::make_unique<exact::EnvironmentSampler>(*ctx.scene.environment);
            const exact::PixelTracer tracer = makeTracer();
            ctx.pass("exact_env_rays", [&] {
                rays = parallelRows(ctx, h, start, [&](size_t pix, float tnear) {
                    return tracer.traceEnvironment(pix, tnear, out);
                });
            });
        } else {
            const auto& l = ctx.currentLight();
            const auto c = l.corners();
            const exact::AreaLight light{c[0], c[1] - c[0], c[3] - c[0], l.forward()};
            const exact::PixelTracer tracer = makeTracer();
            ctx.pass("exact_rays", [&] {
                rays = parallelRows(ctx, h, start, [&](size_t pix, float tnear) {
                    return tracer.tracePixel(light, n_, pix, tnear, out);
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
    exact::PixelTracer makeTracer() const {
        return {position_,          normal_, geometric_, casts_,      rays_,
                environment_.get(), jitter_, seed_,      env_samples_};
    }

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

    int n_;
    bool jitter_;
    std::uint32_t seed_;
    float offset_;
    int env_samples_;
    std::unique_ptr<exact::EnvironmentSampler> environment_;
    int threads_ = 1;
    exact::RayScene rays_;
    std::vector<float> position_, normal_, geometric_;
    std::vector<std::uint8_t> casts_;  // per pixel: its object casts (ShadowRole both, occluder)
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
    },
    // The G-buffer read back (position, normal and facet normal, 48 bytes a pixel; ids, 4 and
    // 1), and the layer it computes (16), on the CPU.
    [](const Params&, std::uint64_t pixels) {
        return MemoryTerms{{"image.width", "exact's readback and ray results (69 bytes a pixel)",
                            saturatingProduct({pixels, 69})}};
    }};

}  // namespace penumbra::techniques
