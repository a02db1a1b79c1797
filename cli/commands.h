// The subcommands of `penumbra`, one file each. Each takes the arguments after its name,
// returns the process exit code, and throws penumbra::Error for bad input.
#pragma once

#include <string>
#include <vector>

namespace penumbra::cli {

using Args = std::vector<std::string>;

int runRender(const Args& args);
int runCompare(const Args& args);
int runTechniques(const Args& args);
int runInfo(const Args& args);
int runSweep(const Args& args);
int runFitLights(const Args& args);

}  // namespace penumbra::cli
