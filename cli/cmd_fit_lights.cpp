// `penumbra fit-lights ENV.exr`: fits uniform area lights to an equirectangular environment
// map (Annen et al. 2008, 4.2) and writes them as JSON, with an optional picture of the fit.
#include <cstdio>
#include <iostream>
#include <optional>
#include <string>

#include "cli/args.h"
#include "cli/commands.h"
#include "renderer/core/atomic_file.h"
#include "renderer/core/json_bounds.h"
#include "renderer/output/preview.h"
#include "renderer/scene/environment_image.h"
#include "renderer/scene/light_fitting.h"
#include "renderer/techniques/css/light_fit_picture.h"

namespace penumbra::cli {
namespace {

constexpr const char* kHelp = R"(usage: penumbra fit-lights ENV.exr [options]

Fits uniform area lights to an equirectangular HDR environment map (.exr or .hdr): the map is
resampled into six cube faces; on each face a light grows from the brightest uncovered texel
while every enlargement adds more than a share t of the enlarged light's energy; its energy is
then taken from the face (leaving a residual), and fitting goes on until every texel is
covered or --max lights are fitted (brightest seeds first, across all faces).

options:
  -o, --output OUT.json  write the lights there (default: standard output)
  --png OUT.png          also draw the map with the fitted lights outlined
  --threshold T          t in (0, 1): enlarge while E_added / E_enlarged > t (default 0.1)
  --max N                at most N lights (default 0: until the faces are covered)
  --shape square|rect    light shape (default rect; the paper fitted squares)
  --face-size N          cube face resolution in texels, 4 to 512 (default 32)
  --residual R           share of a face's mean energy left in each covered texel, in [0, 1)
                         for later lights to grow over (default 0)
  --memory-limit SIZE    refuse a map whose pixels would need more (8G, 512M; default half
                         the physical memory)
  --help                 print this help
)";

}  // namespace

int runFitLights(const Args& args) {
    ArgCursor c("fit-lights", args);
    std::optional<std::string> input, output, png;
    scene::FitSettings settings;
    int face_size = 32;
    std::optional<std::string> v;
    while (!c.done()) {
        if (c.flag("-h", "--help")) {
            std::fputs(kHelp, stdout);
            return 0;
        }
        if ((v = c.option("-o", "--output"))) {
            output = *v;
        } else if ((v = c.option("", "--png"))) {
            png = *v;
        } else if ((v = c.option("", "--threshold"))) {
            settings.threshold = parseDouble(c, "--threshold", *v);
            if (!(settings.threshold > 0 && settings.threshold < 1))
                c.fail("--threshold: expected a number in (0, 1), got '" + quoteText(*v) + "'");
        } else if ((v = c.option("", "--max"))) {
            settings.max_lights = parseInt(c, "--max", *v, 0, 100000);
        } else if ((v = c.option("", "--shape"))) {
            if (*v != "square" && *v != "rect")
                c.fail("--shape: expected square or rect, got '" + quoteText(*v) + "'");
            settings.square = *v == "square";
        } else if ((v = c.option("", "--face-size"))) {
            face_size = parseInt(c, "--face-size", *v, 4, 512);
        } else if ((v = c.option("", "--residual"))) {
            settings.residual = parseDouble(c, "--residual", *v);
            if (!(settings.residual >= 0 && settings.residual < 1))
                c.fail("--residual: expected a number in [0, 1), got '" + quoteText(*v) + "'");
        } else if (parseMemoryLimitFlag(c)) {
        } else if (auto p = c.positional()) {
            if (input) c.fail("unexpected argument '" + quoteText(*p) + "'");
            input = *p;
        } else {
            c.unknown();
        }
    }
    if (!input) c.fail("missing ENV.exr (see penumbra fit-lights --help)");
    if (output) checkOutputPath(*output, "--output");
    if (png) checkOutputPath(*png, "--png");
    const auto image = scene::loadEnvironmentImage(*input);
    const scene::CubeFaces faces = scene::toCubeFaces(*image, face_size);
    const scene::LightFit fit = scene::fitLights(faces, settings);
    nlohmann::json j = scene::lightFitJson(fit, settings, face_size);
    j["source"] = *input;
    const std::string text = j.dump(2) + "\n";
    // Everything is computed before anything is written; each file is written atomically.
    if (png) {
        const auto picture = techniques::css::drawLightFit(*image, fit, face_size);
        output::writePngRgb8(*png, picture.width, picture.height, picture.rgb);
    }
    if (output)
        writeFileAtomically(*output, text);
    else
        std::cout << text;
    std::fprintf(stderr, "penumbra fit-lights: %zu lights, %.1f%% of the energy\n",
                 fit.lights.size(), 100.0 * fit.captured);
    return 0;
}

}  // namespace penumbra::cli
