// Frame image assembly: see frame_image.h.
#include "renderer/frame/frame_image.h"

#include <algorithm>
#include <limits>

#include "renderer/passes/readback.h"

namespace penumbra::frame {

using output::PixelType;

output::Image readFrameImage(const passes::GBuffer& gbuffer, const passes::Shade& shade,
                             const OutputTargets& targets, int lights,
                             const std::string& technique_name,
                             const std::vector<DiagnosticChannel>& diagnostics) {
    const int w = gbuffer.width(), h = gbuffer.height();
    const size_t n = static_cast<size_t>(w) * static_cast<size_t>(h);
    output::Image img;
    img.width = w;
    img.height = h;
    auto beauty = passes::readTexture(shade.beauty(), w, h, 4, GL_RGBA);
    auto position = passes::readTexture(gbuffer.position(), w, h, 4, GL_RGBA);
    auto normal = passes::readTexture(gbuffer.normal(), w, h, 4, GL_RGBA);
    auto id = passes::readTexture(gbuffer.id(), w, h, 1, GL_RED_INTEGER);
    auto visibility = passes::readTexture(shade.visibility(), w, h, 1, GL_RED);

    // add() returns references into img.channels: reserve so none moves while they are held.
    img.channels.reserve(13 + diagnostics.size() + static_cast<size_t>(lights > 1 ? lights : 0));
    auto& r = img.add("R", PixelType::Half);
    auto& g = img.add("G", PixelType::Half);
    auto& b = img.add("B", PixelType::Half);
    auto& a = img.add("A", PixelType::Half);
    auto& z = img.add("Z", PixelType::Float);
    auto& px = img.add("P.X", PixelType::Float);
    auto& py = img.add("P.Y", PixelType::Float);
    auto& pz = img.add("P.Z", PixelType::Float);
    auto& nx = img.add("N.X", PixelType::Half);
    auto& ny = img.add("N.Y", PixelType::Half);
    auto& nz = img.add("N.Z", PixelType::Half);
    auto& vis = img.add("visibility", PixelType::Float);
    auto& ids = img.add("id", PixelType::Float);
    for (size_t i = 0; i < n; ++i) {
        const bool covered = position[4 * i + 3] != 0.0f;
        r.pixels[i] = beauty[4 * i + 0];
        g.pixels[i] = beauty[4 * i + 1];
        b.pixels[i] = beauty[4 * i + 2];
        a.pixels[i] = beauty[4 * i + 3];  // coverage: the share of samples on geometry
        // +inf on the background, where compositors expect it (nothing there, infinitely far).
        z.pixels[i] = covered ? normal[4 * i + 3] : std::numeric_limits<float>::infinity();
        px.pixels[i] = position[4 * i + 0];
        py.pixels[i] = position[4 * i + 1];
        pz.pixels[i] = position[4 * i + 2];
        nx.pixels[i] = normal[4 * i + 0];
        ny.pixels[i] = normal[4 * i + 1];
        nz.pixels[i] = normal[4 * i + 2];
        vis.pixels[i] = visibility[i];
        ids.pixels[i] = id[i];
    }
    // With several lights, each light's own visibility (its layer's .r: the fraction of that
    // light's area the point sees) beside the irradiance-weighted `visibility`.
    for (int l = 0; lights > 1 && l < lights; ++l) {
        auto layer = passes::readTexture(targets.visibility(), w, h, 1, GL_RED, l);
        img.add("visibility." + std::to_string(l), PixelType::Float).pixels = std::move(layer);
    }
    for (size_t d = 0; d < diagnostics.size(); ++d) {
        auto& ch = img.add(technique_name + "." + diagnostics[d].name, PixelType::Float);
        for (int l = 0; l < lights; ++l) {
            auto layer = passes::readTexture(targets.diagnostics()[d], w, h, 1, GL_RED, l);
            for (size_t i = 0; i < n; ++i) {
                if (l == 0)
                    ch.pixels[i] = layer[i];
                else if (diagnostics[d].combine == DiagnosticChannel::Combine::Sum)
                    ch.pixels[i] += layer[i];
                else
                    ch.pixels[i] = std::max(ch.pixels[i], layer[i]);
            }
        }
    }
    return img;
}

}  // namespace penumbra::frame
