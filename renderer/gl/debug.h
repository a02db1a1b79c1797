// KHR_debug output: GL errors become exceptions at the next check, debug groups name passes.
// Works without a debug context once GL_DEBUG_OUTPUT is on.
#pragma once

#include <string>
#include <string_view>

namespace penumbra::gl {

// Enables GL_DEBUG_OUTPUT (synchronous) with a callback that records errors; with VERBOSE
// (--gl-debug) every message is also printed to stderr.
void enableDebugOutput(bool verbose);

// Throws RuntimeError("<where>: GL error: ...") if an error was recorded or glGetError reports
// one since the last check; clears the record.
void checkErrors(std::string_view where);

// RAII debug group (glPushDebugGroup / glPopDebugGroup).
class DebugGroup {
public:
    explicit DebugGroup(std::string_view name);
    ~DebugGroup();
    DebugGroup(const DebugGroup&) = delete;
    DebugGroup& operator=(const DebugGroup&) = delete;
};

}  // namespace penumbra::gl
