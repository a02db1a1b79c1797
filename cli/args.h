// A small hand-written command-line cursor: flags, options with values ("--x V", "--x=V",
// "-x V"), positionals, and typed value parsing with errors that name the flag.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace penumbra::cli {

// An argument no parser accepts: unknown() throws KnownFlags with every flag asked for before
// it, which is how completion and the man page learn each command's flags from its parser.
inline constexpr std::string_view kListFlagsArgument = "--penumbra-list-flags";
struct KnownFlags {
    std::vector<std::string> names;
};

class ArgCursor {
public:
    // COMMAND prefixes messages ("penumbra render: ...").
    ArgCursor(std::string command, std::vector<std::string> args)
        : command_(std::move(command)), args_(std::move(args)) {}

    bool done() const { return index_ >= args_.size(); }
    const std::string& peek() const { return args_[index_]; }
    // True (and consumes it) when the current argument is the boolean flag SHORT or LONG.
    bool flag(std::string_view short_name, std::string_view long_name);
    // The value when the current argument is option SHORT or LONG ("" = no short form).
    // Throws InputError when the value is missing.
    std::optional<std::string> option(std::string_view short_name, std::string_view long_name);
    // The current argument when it does not start with '-' (or is exactly "-").
    std::optional<std::string> positional();
    // Throws the unknown-flag / unexpected-argument error for the current argument.
    [[noreturn]] void unknown() const;
    const std::string& command() const { return command_; }
    [[noreturn]] void fail(const std::string& message) const;

private:
    // Remembers a flag name the parser asked for, so that unknown() can suggest the nearest.
    void noteName(std::string_view short_name, std::string_view long_name);

    std::string command_;
    std::vector<std::string> args_;
    size_t index_ = 0;
    std::vector<std::string> names_;  // every flag asked for so far
};

// Typed values; errors name FLAG ("penumbra compare: --fail: expected a number, got 'x'").
double parseDouble(const ArgCursor& c, std::string_view flag, const std::string& text);
int parseInt(const ArgCursor& c, std::string_view flag, const std::string& text, int min, int max);
// "WxH" -> {W, H}.
std::pair<int, int> parseSize(const ArgCursor& c, std::string_view flag, const std::string& text);

// Consumes "--memory-limit SIZE" (8G, 512M, ...: core/memory_limit.h) and sets the process's
// limit; false when the current argument is another one.
bool parseMemoryLimitFlag(ArgCursor& c);

}  // namespace penumbra::cli
