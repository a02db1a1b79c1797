// `penumbra scene MODEL.glb -o SCENE.json`: the scene `render MODEL.glb` renders, written as a
// plain scene JSON to edit (explicit camera and lights, the glTF named relative to SCENE.json).
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>

#include "cli/args.h"
#include "cli/commands.h"
#include "cli/gltf_flags.h"
#include "renderer/core/atomic_file.h"
#include "renderer/core/json_bounds.h"
#include "renderer/scene/gltf_scene.h"
#include "renderer/scene/scene_json.h"

namespace penumbra::cli {
namespace {

constexpr const char* kHelp = R"(usage: penumbra scene MODEL.glb -o SCENE.json [options]

Writes the scene that `penumbra render MODEL.glb` renders as a plain scene JSON
(penumbra-scene/1) to edit: the glTF's first camera (else a camera that frames the model), its
KHR_lights_punctual lights as rect lights (else one light above the model), the model and a
floor, every value explicit. The glTF is named by a path relative to SCENE.json's folder. The
file is written atomically; an existing SCENE.json is replaced.

options:
  -o, --output SCENE.json  where to write the scene (required; ends in .json)
      --size WxH           image size the camera is framed for (default 1024x768)
      --light-size W[xH]   the glTF's lights as rect lights of this size, metres (default: a
                           quarter of the model's bounding radius; the default light: the
                           radius)
      --no-floor           no floor under the model
  -h, --help               this help
)";

}  // namespace

int runScene(const Args& args) {
    ArgCursor c("scene", args);
    std::optional<std::string> input, output;
    scene::GltfSceneOptions options;
    scene::ImageSettings image;
    while (!c.done()) {
        if (c.flag("-h", "--help")) {
            std::fputs(kHelp, stdout);
            return 0;
        }
        if (auto v = c.option("-o", "--output")) {
            if (v->empty()) c.fail("--output: empty path");
            output = *v;
        } else if (auto size = c.option("", "--size")) {
            const auto [w, h] = parseSize(c, "--size", *size);
            if (w > scene::kMaxImageSize || h > scene::kMaxImageSize)
                c.fail("--size: " + quoteText(*size) + " exceeds " +
                       std::to_string(scene::kMaxImageSize) + " pixels a side");
            image.width = w;
            image.height = h;
        } else if (parseGltfSceneFlag(c, options)) {
        } else if (auto p = c.positional()) {
            if (input) c.fail("unexpected argument '" + quoteText(*p) + "': one model per scene");
            input = *p;
        } else {
            c.unknown();
        }
    }
    if (!input) c.fail("missing MODEL.glb (see penumbra scene --help)");
    if (!scene::isGltfPath(*input))
        c.fail("'" + quoteText(*input) + "' is not a .gltf or .glb file");
    if (!output) c.fail("missing -o SCENE.json (see penumbra scene --help)");
    if (std::filesystem::path(*output).extension() != ".json")
        c.fail("--output: " + quoteText(*output) + ": the file name must end in .json");
    checkOutputPath(*output, "--output");
    scene::AssetStore assets;
    const nlohmann::ordered_json doc = scene::gltfSceneFor(*input, *output, options, image, assets);
    writeFileAtomically(*output, doc.dump(2) + "\n");
    return 0;
}

}  // namespace penumbra::cli
