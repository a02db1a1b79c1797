// `penumbra`: dispatches to one subcommand and turns errors into the documented exit codes.
#include <algorithm>
#include <cstdio>
#include <cstring>
#include <exception>
#include <iostream>
#include <string>

#include "cli/args.h"
#include "cli/commands.h"
#include "penumbra/version.h"
#include "renderer/core/did_you_mean.h"
#include "renderer/core/error.h"

namespace {

using namespace penumbra;

// The usage text, from the command table.
std::string usage() {
    std::string text = "usage: penumbra COMMAND [options]\n\ncommands:\n";
    for (const auto& c : cli::allCommands()) {
        std::string synopsis(c.synopsis);
        synopsis.resize(std::max<size_t>(synopsis.size() + 1, 36), ' ');
        text += "  " + synopsis + std::string(c.summary) + "\n";
    }
    return text +
           "  --version                           print the version\n\n"
           "Every command answers --help and --version.\n";
}

}  // namespace

int main(int argc, char** argv) {
    using namespace penumbra;
    if (argc < 2) {
        std::fputs(usage().c_str(), stderr);
        return static_cast<int>(ExitCode::BadInput);
    }
    std::string command = argv[1];
    cli::Args args(argv + 2, argv + argc);
    try {
        if (command == "--help" || command == "-h" || command == "help") {
            std::fputs(usage().c_str(), stdout);
            return 0;
        }
        // `penumbra --version` and `penumbra COMMAND ... --version` alike.
        if (command == "--version" ||
            std::find(args.begin(), args.end(), std::string("--version")) != args.end()) {
            std::printf("penumbra %s (%s)\n", PENUMBRA_VERSION, PENUMBRA_COMMIT);
            return 0;
        }
        if (const auto* c = cli::findCommand(command)) return c->run(args);
        if (command == "completion") return cli::runCompletion(args);
        if (command == "manpage") return cli::runManpage(args);
        std::vector<std::string> names{"help"};
        for (const auto& c : cli::allCommands()) names.emplace_back(c.name);
        const std::string near = nearestName(command, names);
        std::fprintf(stderr, "penumbra: %s: unknown command (%ssee penumbra --help)\n",
                     command.c_str(), near.empty() ? "" : ("did you mean " + near + "? ").c_str());
        return static_cast<int>(ExitCode::BadInput);
    } catch (const cli::KnownFlags&) {  // the completion generator's argument, typed by hand
        std::fprintf(stderr, "penumbra: %s: unknown flag (see --help)\n", command.c_str());
        return static_cast<int>(ExitCode::BadInput);
    } catch (const Error& e) {
        std::fprintf(stderr, "penumbra: %s\n", e.what());
        return static_cast<int>(e.code());
    } catch (const std::exception& e) {
        std::fprintf(stderr, "penumbra: %s: internal error: %s\n", command.c_str(), e.what());
        return static_cast<int>(ExitCode::RuntimeFailure);
    }
}
