// Atomic writes: see atomic_file.h.
#include "renderer/core/atomic_file.h"

#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <fstream>
#include <iterator>
#include <utility>

#include "renderer/core/error.h"
#include "renderer/core/process_clock.h"
#include "renderer/core/regular_file.h"

namespace penumbra {
namespace {
constexpr const char* kOnlyRegular = " (an output replaces only a regular file)";
thread_local AtomicGroup* current_group = nullptr;

// The temporaries being written or awaiting a commit, for the signal handler: a slot's path is
// complete while its state is kHeld. Lock-free atomics only, so the handler may read them.
constexpr int kFree = 0, kFilling = 1, kHeld = 2;
struct TemporarySlot {
    std::atomic<int> state{kFree};
    char path[4096];
};
TemporarySlot g_temporaries[64];
static_assert(std::atomic<int>::is_always_lock_free, "the signal handler reads the slots");

// The slot holding TMP (absolute), or -1 when none is free or the path is too long (then a
// signal leaves that file for removeStaleTemporaries).
int holdTemporary(const std::filesystem::path& tmp) {
    std::error_code ec;
    const std::string path = std::filesystem::absolute(tmp, ec).string();
    if (ec || path.size() >= sizeof(TemporarySlot::path)) return -1;
    for (int i = 0; i < static_cast<int>(std::size(g_temporaries)); ++i) {
        TemporarySlot& slot = g_temporaries[i];
        int expected = kFree;
        if (!slot.state.compare_exchange_strong(expected, kFilling)) continue;
        std::memcpy(slot.path, path.c_str(), path.size() + 1);
        slot.state.store(kHeld);
        return i;
    }
    return -1;
}

void releaseTemporary(int slot) {
    if (slot >= 0) g_temporaries[slot].state.store(kFree);
}

extern "C" void removeTemporariesAndEnd(int signal_number) {
    for (TemporarySlot& slot : g_temporaries)
        if (slot.state.load() == kHeld) ::unlink(slot.path);
    ::signal(signal_number, SIG_DFL);
    ::raise(signal_number);
}

void renameIntoPlace(const std::filesystem::path& tmp, const std::filesystem::path& path) {
    std::error_code ec;
    std::filesystem::rename(tmp, path, ec);
    if (ec) {
        const std::string why = ec.message();  // before remove() overwrites EC
        std::filesystem::remove(tmp, ec);
        throw RuntimeError(path.string() + ": cannot rename into place: " + why);
    }
}

// When process PID started, in seconds since the epoch (its start ticks and the boot time of
// /proc/stat), or -1 when unknown.
double processStart(long pid) {
    const double ticks = processStartTicks(pid);
    std::ifstream boot("/proc/stat");
    std::string key;
    double btime = -1;
    while (boot >> key)
        if (key == "btime" && boot >> btime) break;
    if (btime < 0 || ticks < 0) return -1;
    return btime + ticks / static_cast<double>(::sysconf(_SC_CLK_TCK));
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
    for (const Pending& p : pending_) {
        std::filesystem::remove(p.tmp, ec);
        releaseTemporary(p.slot);
    }
}

void AtomicGroup::commit() {
    for (Pending& p : pending_) {
        renameIntoPlace(p.tmp, p.path);  // on failure the destructor removes the rest
        releaseTemporary(std::exchange(p.slot, -1));
    }
    pending_.clear();
}

void removeTemporariesOnSignal() {
    for (int signal_number : {SIGINT, SIGTERM, SIGHUP}) {
        struct sigaction old {};
        if (::sigaction(signal_number, nullptr, &old) != 0 || old.sa_handler != SIG_DFL) continue;
        struct sigaction action {};
        action.sa_handler = removeTemporariesAndEnd;
        sigemptyset(&action.sa_mask);
        ::sigaction(signal_number, &action, nullptr);
    }
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
    const int slot = holdTemporary(tmp);
    try {
        write(tmp);
    } catch (const Error&) {
        std::filesystem::remove(tmp, ec);
        releaseTemporary(slot);
        throw;
    } catch (const std::exception& e) {
        std::filesystem::remove(tmp, ec);
        releaseTemporary(slot);
        throw RuntimeError(path.string() + ": write failed: " + e.what());
    }
    if (current_group) {
        current_group->pending_.push_back({tmp, path, slot});
        return;
    }
    try {
        renameIntoPlace(tmp, path);
    } catch (...) {
        releaseTemporary(slot);
        throw;
    }
    releaseTemporary(slot);
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
