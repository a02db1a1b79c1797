// Progress of a render job on stderr (a terminal only): "frame i of n (frame f), pass, elapsed,
// ETA" on one line that is rewritten in place and cut to the terminal's width, never wrapped.
#pragma once

#include <chrono>
#include <cstddef>
#include <string>

namespace penumbra::app {

// A duration as a person reads it: "0.4s", "12s", "3m 05s", "1h 02m".
std::string formatDuration(double seconds);

// TEXT cut to at most WIDTH - 1 columns (the last column would wrap on some terminals).
std::string fitToWidth(const std::string& text, int width);

// The terminal width of stderr: TIOCGWINSZ, else $COLUMNS, else 80.
int terminalWidth();

class Progress {
public:
    Progress(bool enabled, std::size_t total);
    void frame(std::size_t index, int frame);
    void pass(const std::string& name) { show(name, false); }
    void done();  // ends the line (before other messages)

private:
    using Clock = std::chrono::steady_clock;
    void show(const std::string& pass, bool force);
    bool enabled_;
    bool shown_ = false;
    std::size_t total_, index_ = 0;
    int frame_ = 0;
    Clock::time_point start_, last_;
};

}  // namespace penumbra::app
