// The render job's progress line: see render_job_progress.h.
#include "renderer/app/render_job_progress.h"

#include <sys/ioctl.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace penumbra::app {

std::string formatDuration(double seconds) {
    char buf[32];
    if (!(seconds >= 0)) seconds = 0;
    if (seconds < 10) {
        std::snprintf(buf, sizeof buf, "%.1fs", seconds);
        return buf;
    }
    const long s = std::lround(seconds);
    if (s < 60)
        std::snprintf(buf, sizeof buf, "%lds", s);
    else if (s < 3600)
        std::snprintf(buf, sizeof buf, "%ldm %02lds", s / 60, s % 60);
    else
        std::snprintf(buf, sizeof buf, "%ldh %02ldm", s / 3600, (s % 3600) / 60);
    return buf;
}

std::string fitToWidth(const std::string& text, int width) {
    const std::size_t room = width > 1 ? static_cast<std::size_t>(width - 1) : 0;
    return text.size() <= room ? text : text.substr(0, room);
}

int terminalWidth() {
    winsize ws{};
    if (::ioctl(STDERR_FILENO, TIOCGWINSZ, &ws) == 0 && ws.ws_col > 0) return ws.ws_col;
    if (const char* columns = std::getenv("COLUMNS")) {
        const int n = std::atoi(columns);
        if (n > 0) return n;
    }
    return 80;
}

Progress::Progress(bool enabled, std::size_t total)
    : enabled_(enabled), total_(total), start_(Clock::now()) {}

void Progress::frame(std::size_t index, int frame) {
    index_ = index;
    frame_ = frame;
    show("", true);
}

void Progress::done() {
    if (enabled_ && shown_) std::fputs("\n", stderr);
    shown_ = false;
}

void Progress::show(const std::string& pass, bool force) {
    if (!enabled_) return;
    const auto now = Clock::now();
    if (!force && now - last_ < std::chrono::milliseconds(100)) return;
    last_ = now;
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    std::string line = "penumbra: frame " + std::to_string(index_ + 1) + " of " +
                       std::to_string(total_) + " (frame " + std::to_string(frame_) + ")";
    if (!pass.empty()) line += " " + pass;
    line += ", elapsed " + formatDuration(elapsed);
    if (index_ > 0)
        line += ", ETA " + formatDuration(elapsed / static_cast<double>(index_) *
                                          static_cast<double>(total_ - index_));
    // \r and erase-line rewrite the line in place; cut, it never wraps onto a second row.
    std::fprintf(stderr, "\r\033[K%s", fitToWidth(line, terminalWidth()).c_str());
    std::fflush(stderr);
    shown_ = true;
}

}  // namespace penumbra::app
