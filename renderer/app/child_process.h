// Child processes without a shell: argv spawned (argv[0] looked up in PATH) and waited for, so
// that no argument is ever quoted or interpreted.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace penumbra::app {

// Spawns ARGS and waits; its stdout goes to /dev/null when QUIET, its stdin comes from
// STDIN_FILE when given. True when it ran and exited 0.
bool spawnAndWait(const std::vector<std::string>& args, bool quiet,
                  const std::filesystem::path& stdin_file = {});

}  // namespace penumbra::app
