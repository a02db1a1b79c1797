// The subcommands of `penumbra`, one file each. Each takes the arguments after its name,
// returns the process exit code, and throws penumbra::Error for bad input.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace penumbra::cli {

using Args = std::vector<std::string>;

int runRender(const Args& args);
int runCompare(const Args& args);
int runTechniques(const Args& args);
int runInfo(const Args& args);
int runSweep(const Args& args);
int runFitLights(const Args& args);
int runContactSheet(const Args& args);
int runScene(const Args& args);
// Hidden helpers of the install: `penumbra completion bash`, `penumbra manpage`.
int runCompletion(const Args& args);
int runManpage(const Args& args);

// The table of commands: dispatch, usage, "did you mean", completion and the man page.
struct Command {
    std::string_view name;
    std::string_view synopsis;  // "render SCENE|MODEL.glb [options]"
    std::string_view summary;   // one line
    int (*run)(const Args&);
};
std::span<const Command> allCommands();
const Command* findCommand(std::string_view name);

// The flags COMMAND's parser knows (long and short), asked of the parser itself.
std::vector<std::string> commandFlags(const Command& command);

}  // namespace penumbra::cli
