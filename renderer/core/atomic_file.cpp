// Atomic writes: see atomic_file.h.
#include "renderer/core/atomic_file.h"

#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <fstream>
#include <sstream>

#include "renderer/core/error.h"
#include "renderer/core/regular_file.h"

namespace penumbra {
namespace {
constexpr const char* kOnlyRegular = " (an output replaces only a regular file)";
thread_local AtomicGroup* current_group = nullptr;

void renameIntoPlace(const std::filesystem::path& tmp, const std::filesystem::path& path) {
    std::error_code ec;
    std::filesystem::rename(tmp, path, ec);
    if (ec) {
        const std::string why = ec.message();  // before remove() overwrites EC
        std::filesystem::remove(tmp, ec);
        throw RuntimeError(path.string() + ": cannot rename into place: " + why);
    }
}

// When process PID started, in seconds since the epoch (/proc/PID/stat field 22 and the boot
// time of /proc/stat), or -1 when unknown.
double processStart(long pid) {
    std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
    std::string text;
    std::getline(stat, text);
    const size_t paren = text.rfind(')');  // the command name may hold spaces
    if (paren == std::string::npos) return -1;
    std::istringstream fields(text.substr(paren + 2));
    std::string field;
    for (int i = 3; i <= 22 && fields >> field; ++i) {
    }
    std::ifstream boot("/proc/stat");
    std::string key;
    double btime = -1;
    while (boot >> key)
        if (key == "btime" && boot >> btime) break;
    if (btime < 0 || field.empty()) return -1;
    return btime + std::stod(field) / static_cast<double>(::sysconf(_SC_CLK_TCK));
}

// True when process PID is gone, or was started after TIME (its PID was reused since).
bool writerIsGone(long pid, std::filesystem::file_time_type time) {
    if (pid <= 0 || pid == ::getpid()) return pid <= 0;
    if (::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH) return true;
    const double started = processStart(pid);
    const auto written = std::chrono::file_clock::to_sys(time).time_since_epoch();
    // A second of slack: the boot time and the start ticks are coarse.
    return started > 0 && started > std::chrono::duration<double>(written).count() + 1.0;
}
}  // namespace

AtomicGroup::AtomicGroup() : outer_(current_group) {
    current_group = this;
}

AtomicGroup::~AtomicGroup() {
    current_group = outer_;
    std::error_code ec;
    for (const auto& [tmp, path] : pending_) std::filesystem::remove(tmp, ec);
}

void AtomicGroup::commit() {
    for (size_t i = 0; i < pending_.size(); ++i) {
        renameIntoPlace(pending_[i].first, pending_[i].second);
        pending_[i].first.clear();
    }
    pending_.clear();
}

int removeStaleTemporaries(const std::filesystem::path& path) {
    const std::filesystem::path dir = path.has_parent_path() ? path.parent_path() : ".";
    std::string prefix = ".";  // built in steps: GCC 12 warns falsely on "." + string + "."
    prefix += path.filename().string();
    prefix += '.';
    std::error_code ec;
    int removed = 0;
    for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
        const std::string name = entry.path().filename().string();
        if (name.size() <= prefix.size() + 4 || name.rfind(prefix, 0) != 0 ||
            !name.ends_with(".tmp") || !entry.is_regular_file(ec))
            continue;
        const std::string digits = name.substr(prefix.size(), name.size() - prefix.size() - 4);
        if (digits.empty() || digits.find_first_not_of("0123456789") != std::string::npos) continue;
        if (writerIsGone(std::stol(digits), entry.last_write_time(ec)) &&
            std::filesystem::remove(entry.path(), ec))
            ++removed;
    }
    return removed;
}

std::filesystem::path temporaryPathFor(const std::filesystem::path& path) {
    std::filesystem::path dir = path.parent_path();
    std::string name = ".";
    name += path.filename().string();
    name += ".";
    name += std::to_string(::getpid());
    name += ".tmp";
    return dir.empty() ? std::filesystem::path(name) : dir / name;
}

void writeAtomically(const std::filesystem::path& path,
                     const std::function<void(const std::filesystem::path&)>& write) {
    std::error_code ec;
    if (path.has_parent_path()) {
        std::filesystem::create_directories(path.parent_path(), ec);
        if (ec)
            throw RuntimeError(path.parent_path().string() +
                               ": cannot create folder: " + ec.message());
    }
    // rename() replaces whatever is at PATH: a device node, a FIFO, a link, an empty folder.
    if (const std::string why = notReplaceableReason(path); !why.empty())
        throw RuntimeError(path.string() + ": " + why + kOnlyRegular);
    const std::filesystem::path tmp = temporaryPathFor(path);
    try {
        write(tmp);
    } catch (const Error&) {
        std::filesystem::remove(tmp, ec);
        throw;
    } catch (const std::exception& e) {
        std::filesystem::remove(tmp, ec);
        throw RuntimeError(path.string() + ": write failed: " + e.what());
    }
    if (current_group) {
        current_group->pending_.emplace_back(tmp, path);
        return;
    }
    renameIntoPlace(tmp, path);
}

void checkOutputPath(const std::filesystem::path& path, const std::string& label) {
    if (const std::string why = notReplaceableReason(path); !why.empty())
        throw InputError(label + ": " + path.string() + ": " + why + kOnlyRegular);
}

void writeFileAtomically(const std::filesystem::path& path, const std::string& text) {
    writeAtomically(path, [&](const std::filesystem::path& tmp) {
        std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
        out.write(text.data(), static_cast<std::streamsize>(text.size()));
        out.close();
        if (!out) throw RuntimeError(tmp.string() + ": " + std::strerror(errno));
    });
}

}  // namespace penumbra
