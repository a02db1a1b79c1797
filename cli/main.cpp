// `penumbra`: dispatches to one subcommand and turns errors into the documented exit codes.
#include <cstdio>
#include <cstring>
#include <exception>
#include <iostream>
#include <string>

#include "cli/commands.h"
#include "penumbra/version.h"
#include "renderer/core/error.h"

namespace {

constexpr const char* kUsage = R"(usage: penumbra COMMAND [options]

commands:
  render SCENE.json [options]     render frames to EXR + timing JSON
  compare REF.exr TEST.exr        golden-image diff with idiff-style thresholds
  techniques [NAME] [--json]      list techniques and their parameters
  info [--json]                   OpenGL backends found and the one chosen
  sweep SCENE.json --vary ... -o DIR   error and time over a cartesian product of values
  fit-lights ENV.exr [options]    fit area lights to an environment map (JSON + picture)
  --version                       print the version

Every command answers --help.
)";

}  // namespace

int main(int argc, char** argv) {
    using namespace penumbra;
    if (argc < 2) {
        std::fputs(kUsage, stderr);
        return static_cast<int>(ExitCode::BadInput);
    }
    std::string command = argv[1];
    cli::Args args(argv + 2, argv + argc);
    try {
        if (command == "--help" || command == "-h" || command == "help") {
            std::fputs(kUsage, stdout);
            return 0;
        }
        if (command == "--version") {
            std::printf("penumbra %s (%s)\n", PENUMBRA_VERSION, PENUMBRA_COMMIT);
            return 0;
        }
        if (command == "render") return cli::runRender(args);
        if (command == "compare") return cli::runCompare(args);
        if (command == "techniques") return cli::runTechniques(args);
        if (command == "info") return cli::runInfo(args);
        if (command == "sweep") return cli::runSweep(args);
        if (command == "fit-lights") return cli::runFitLights(args);
        std::fprintf(stderr, "penumbra: unknown command '%s' (see penumbra --help)\n",
                     command.c_str());
        return static_cast<int>(ExitCode::BadInput);
    } catch (const Error& e) {
        std::fprintf(stderr, "penumbra: %s\n", e.what());
        return static_cast<int>(e.code());
    } catch (const std::exception& e) {
        std::fprintf(stderr, "penumbra: %s: internal error: %s\n", command.c_str(), e.what());
        return static_cast<int>(ExitCode::RuntimeFailure);
    }
}
