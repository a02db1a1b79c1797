// Frame image assembly: see frame_image.h.
#include "renderer/frame/frame_image.h"

#include <algorithm>
#include <cstdint>
#include <iterator>
#include <limits>

#include "renderer/core/error.h"

namespace penumbra::frame {

using output::Fill;
using output::PixelType;

void FrameReadback::wait() {
    fence.wait("readback");
}

FrameReadback startFrameReadback(passes::ReadbackPool& pool, const passes::GBuffer& gbuffer,
                                 const passes::Shade& shade, const OutputTargets& targets,
                                 int lights, int scene_lights, const std::string& technique_name,
                                 const std::vector<DiagnosticChannel>& diagnostics) {
    const int w = gbuffer.width(), h = gbuffer.height();
    FrameReadback r;
    r.width = w;
    r.height = h;
    r.lights = lights;
    r.technique_name = technique_name;
    r.diagnostics = diagnostics;
    auto rgba = [&](const gl::Texture& t) { return pool.read(t, w, h, GL_RGBA, GL_FLOAT, 16); };
    auto red = [&](const gl::Texture& t, int layer) {
        return pool.read(t, w, h, GL_RED, GL_FLOAT, 4, layer);
    };
    r.beauty = rgba(shade.beauty());
    r.position = rgba(gbuffer.position());
    r.normal = rgba(gbuffer.normal());
    r.id = pool.read(gbuffer.id(), w, h, GL_RED_INTEGER, GL_INT, 4);
    r.visibility = red(shade.visibility(), -1);
    // With several scene lights, each one's own visibility (its layer's .r: the fraction of that
    // light's area the point sees) beside the irradiance-weighted `visibility`. Not for the
    // lights made of an environment: hundreds of them (`reference`'s env_samples) would be
    // hundreds of channels.
    for (int l = 0; scene_lights > 1 && l < std::min(scene_lights, lights); ++l)
        r.light_visibility.push_back(red(targets.visibility(), l));
    for (size_t d = 0; d < diagnostics.size(); ++d) {
        r.diagnostic.emplace_back();
        for (int l = 0; l < lights; ++l)
            r.diagnostic.back().push_back(red(targets.diagnostics()[d], l));
    }
    r.fence = pool.fence();
    return r;
}

namespace {

// A single-float layer as a channel, GL's bottom-up rows turned top first.
void copyRows(const float* src, int w, int h, std::vector<float>& dst) {
    const size_t row = static_cast<size_t>(w);
    for (int y = 0; y < h; ++y)
        std::copy_n(src + row * static_cast<size_t>(h - 1 - y), row,
                    dst.begin() + static_cast<std::ptrdiff_t>(row * static_cast<size_t>(y)));
}

// Diagnostic D of every light combined (sum or max) into CH.
void combineDiagnostic(const FrameReadback& r, size_t d, std::vector<float>& ch) {
    std::vector<float> layer(r.lights > 1 ? ch.size() : 0);
    for (int l = 0; l < r.lights; ++l) {
        copyRows(r.diagnostic[d][static_cast<size_t>(l)]->as<float>(), r.width, r.height,
                 l == 0 ? ch : layer);
        if (l == 0) continue;
        for (size_t i = 0; i < ch.size(); ++i)
            ch[i] = r.diagnostics[d].combine == DiagnosticChannel::Combine::Sum
                        ? ch[i] + layer[i]
                        : std::max(ch[i], layer[i]);
    }
}

}  // namespace

output::Image assembleFrameImage(const FrameReadback& rb, output::PixelBuffers* buffers) {
    if (rb.fence.pending())
        throw RuntimeError("readback: assembled before its copies were waited for");
    const int w = rb.width, h = rb.height;
    output::Image img;
    img.width = w;
    img.height = h;
    img.buffers = buffers;
    const float* beauty = rb.beauty->as<float>();
    const float* position = rb.position->as<float>();
    const float* normal = rb.normal->as<float>();
    const std::int32_t* id = rb.id->as<std::int32_t>();
    const float* visibility = rb.visibility->as<float>();
    // add() returns references into img.channels: reserve so none moves while they are held.
    img.channels.reserve(13 + rb.diagnostics.size() + rb.light_visibility.size());
    // Each channel is a component of a texture read back (STRIDE floats a pixel), but Z (+inf on
    // the background, where compositors expect it: nothing there, infinitely far) and the id.
    struct Gathered {
        const char* name;
        PixelType type;
        const float* source;  // null: Z or id
        size_t stride, component;
    };
    const Gathered gathered[] = {
        {"R", PixelType::Half, beauty, 4, 0},
        {"G", PixelType::Half, beauty, 4, 1},
        {"B", PixelType::Half, beauty, 4, 2},
        {"A", PixelType::Half, beauty, 4, 3},  // coverage: the share of samples on geometry
        {"Z", PixelType::Float, nullptr, 0, 0},
        {"P.X", PixelType::Float, position, 4, 0},
        {"P.Y", PixelType::Float, position, 4, 1},
        {"P.Z", PixelType::Float, position, 4, 2},
        {"N.X", PixelType::Half, normal, 4, 0},
        {"N.Y", PixelType::Half, normal, 4, 1},
        {"N.Z", PixelType::Half, normal, 4, 2},
        {"visibility", PixelType::Float, visibility, 1, 0},
        {"id", PixelType::Float, nullptr, 0, 0},
    };
    std::vector<float*> out;
    for (const Gathered& c : gathered)
        out.push_back(img.add(c.name, c.type, Fill::Undefined).pixels.data());
    float* z = out[4];     // the table's Z
    float* ids = out[12];  // and id
    // A row at a time, one channel after the other: the source rows stay in the cache, and no
    // loop writes 13 streams at once (reused buffers share their page offsets, and 13 streams
    // of one page offset thrash the cache's sets).
    const size_t width = static_cast<size_t>(w);
    for (int y = 0; y < h; ++y) {
        const size_t row = static_cast<size_t>(y) * width;          // top first
        const size_t src = static_cast<size_t>(h - 1 - y) * width;  // GL: bottom first
        for (size_t k = 0; k < std::size(gathered); ++k) {
            const Gathered& c = gathered[k];
            if (!c.source) continue;
            const float* from = c.source + src * c.stride + c.component;
            float* to = out[k] + row;
            for (size_t x = 0; x < width; ++x) to[x] = from[x * c.stride];
        }
        for (size_t x = 0; x < width; ++x) {
            const size_t s = src + x;
            z[row + x] = position[4 * s + 3] != 0.0f ? normal[4 * s + 3]
                                                     : std::numeric_limits<float>::infinity();
            ids[row + x] = static_cast<float>(id[s]);
        }
    }
    // Each light's visibility, 1 on the background (Z +inf) as `visibility` is: what a technique
    // left in its layer there (0 or 1, by technique) means nothing, and golden diffs would see it.
    for (size_t l = 0; l < rb.light_visibility.size(); ++l) {
        auto& light =
            img.add("visibility." + std::to_string(l), PixelType::Float, Fill::Undefined).pixels;
        copyRows(rb.light_visibility[l]->as<float>(), w, h, light);
        for (size_t i = 0; i < light.size(); ++i)
            if (z[i] == std::numeric_limits<float>::infinity()) light[i] = 1.0f;
    }
    for (size_t d = 0; d < rb.diagnostics.size(); ++d)
        combineDiagnostic(rb, d,
                          img.add(rb.technique_name + "." + rb.diagnostics[d].name,
                                  PixelType::Float, Fill::Undefined)
                              .pixels);
    return img;
}

}  // namespace penumbra::frame
