// The command table (see commands.h) and each command's flags, learnt from its own parser.
#include "cli/commands.h"

#include "cli/args.h"

namespace penumbra::cli {
namespace {

constexpr Command kCommands[] = {
    {"render", "render SCENE|MODEL.glb [options]", "render frames to EXR + timing JSON", runRender},
    {"scene", "scene MODEL.glb -o SCENE.json", "a glTF as an editable scene JSON (camera, lights)",
     runScene},
    {"compare", "compare REF.exr TEST.exr [options]",
     "golden-image diff with idiff-style thresholds", runCompare},
    {"techniques", "techniques [NAME] [--json]", "list techniques and their parameters",
     runTechniques},
    {"info", "info [--json]", "OpenGL backends found and the one chosen", runInfo},
    {"sweep", "sweep SCENE.json --vary ... -o DIR",
     "error and time over a cartesian product of values", runSweep},
    {"fit-lights", "fit-lights ENV.exr [options]",
     "fit area lights to an environment map (JSON + picture)", runFitLights},
    {"contact-sheet", "contact-sheet IMAGE... -o SHEET.png",
     "a labelled grid of images, frames or a sweep's runs", runContactSheet},
};

}  // namespace

std::span<const Command> allCommands() {
    return kCommands;
}

const Command* findCommand(std::string_view name) {
    for (const Command& c : kCommands)
        if (c.name == name) return &c;
    return nullptr;
}

std::vector<std::string> commandFlags(const Command& command) {
    try {
        command.run({std::string(kListFlagsArgument)});
    } catch (const KnownFlags& known) {
        return known.names;
    }
    return {};
}

}  // namespace penumbra::cli
