// Process start times: see process_clock.h.
#include "renderer/core/process_clock.h"

#include <time.h>
#include <unistd.h>

#include <fstream>
#include <sstream>
#include <string>

namespace penumbra {

double processStartTicks(long pid) {
    std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
    std::string text;
    std::getline(stat, text);
    const size_t paren = text.rfind(')');  // the command name may hold spaces
    if (paren == std::string::npos) return -1;
    std::istringstream fields(text.substr(paren + 2));
    std::string field;
    for (int i = 3; i <= 22 && fields >> field; ++i) {
    }
    return field.empty() ? -1 : std::stod(field);
}

double processAgeMs() {
    const double started = processStartTicks(::getpid());
    const long ticks = ::sysconf(_SC_CLK_TCK);
    timespec now{};
    if (started < 0 || ticks <= 0 || ::clock_gettime(CLOCK_BOOTTIME, &now) != 0) return -1;
    return static_cast<double>(now.tv_sec) * 1e3 + static_cast<double>(now.tv_nsec) / 1e6 -
           started * 1000.0 / static_cast<double>(ticks);
}

}  // namespace penumbra
