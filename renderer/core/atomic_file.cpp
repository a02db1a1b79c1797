// Atomic writes: see atomic_file.h.
#include "renderer/core/atomic_file.h"

#include <pthread.h>
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <condition_variable>
#include <cstring>
#include <fstream>
#include <mutex>
#include <thread>
#include <vector>

#include "renderer/core/error.h"
#include "renderer/core/process_clock.h"
#include "renderer/core/regular_file.h"

namespace penumbra {
namespace {
constexpr const char* kOnlyRegular = " (an output replaces only a regular file)";
thread_local AtomicGroup* current_group = nullptr;

// The temporaries this process holds (being written, or written and awaiting a group's
// commit) and whether a signal is ending it. Every change is made under the lock, which the
// signal thread (removeTemporariesOnSignal) keeps from the moment it removes them until the
// process ends: no temporary is created or renamed after that. Never destroyed, so a signal
// during exit still finds it.
struct Temporaries {
    std::mutex mutex;
    std::condition_variable changed;
    std::vector<std::string> held;  // absolute paths
    int writing = 0;                // writes under way (their files may not exist yet)
    bool ending = false;
};
Temporaries& temporaries() {
    static auto* t = new Temporaries;
    return *t;
}

// How long a signal waits for the writes under way to end before it removes the temporaries
// and ends the process anyway (a write that then creates its file leaves it behind).
constexpr auto kWriteGrace = std::chrono::seconds(10);

std::string absolutePath(const std::filesystem::path& path) {
    std::error_code ec;
    const std::filesystem::path abs = std::filesystem::absolute(path, ec);
    return ec ? path.string() : abs.string();
}

// Holds TMP before its file is created, as a write under way. Once a signal is ending the
// process no write starts: the calling thread waits for the end.
void beginWrite(const std::string& tmp) {
    Temporaries& t = temporaries();
    std::unique_lock lock(t.mutex);
    t.changed.wait(lock, [&] { return !t.ending; });
    t.held.push_back(tmp);
    ++t.writing;
}

// The write of a held temporary has returned (its file complete, or removed on failure).
void endWrite() {
    Temporaries& t = temporaries();
    std::unique_lock lock(t.mutex);
    --t.writing;
    t.changed.notify_all();
    t.changed.wait(lock, [&] { return !t.ending; });
}

// Renames TMP to PATH (or, with PATH empty, removes TMP) and stops holding it; under the lock,
// so a signal never removes a file being renamed. Throws RuntimeError when the rename fails.
void settle(const std::string& tmp, const std::filesystem::path& path) {
    Temporaries& t = temporaries();
    std::unique_lock lock(t.mutex);
    t.changed.wait(lock, [&] { return !t.ending; });
    if (const auto it = std::find(t.held.begin(), t.held.end(), tmp); it != t.held.end())
        t.held.erase(it);
    std::error_code ec;
    if (path.empty()) {
        std::filesystem::remove(tmp, ec);
        return;
    }
    std::filesystem::rename(tmp, path, ec);
    if (ec) {
        const std::string why = ec.message();  // before remove() overwrites EC
        std::filesystem::remove(tmp, ec);
        throw RuntimeError(path.string() + ": cannot rename into place: " + why);
    }
}

// The signal thread: waits for one of SIGNALS, lets the writes under way end, removes every
// held temporary and ends the process by that signal, the lock still held.
[[noreturn]] void endOnSignal(sigset_t signals) {
    int signal_number = 0;
    while (::sigwait(&signals, &signal_number) != 0) {
    }
    Temporaries& t = temporaries();
    std::unique_lock lock(t.mutex);
    t.ending = true;
    t.changed.wait_for(lock, kWriteGrace, [&] { return t.writing == 0; });
    for (const std::string& path : t.held) ::unlink(path.c_str());
    ::signal(signal_number, SIG_DFL);
    sigset_t one;
    sigemptyset(&one);
    sigaddset(&one, signal_number);
    ::pthread_sigmask(SIG_UNBLOCK, &one, nullptr);
    ::raise(signal_number);
    ::_exit(128 + signal_number);  // not reached: the signal's default action ends the process
}

// A thread that began before the signals were blocked may still receive one: pass it on.
pthread_t g_signal_thread;
extern "C" void forwardToSignalThread(int signal_number) {
    ::pthread_kill(g_signal_thread, signal_number);
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
    for (const Pending& p : pending_) settle(p.tmp, {});
}

void AtomicGroup::commit() {
    // In the order written; when a rename fails, the destructor removes the rest.
    for (; !pending_.empty(); pending_.erase(pending_.begin()))
        settle(pending_.front().tmp, pending_.front().path);
}

void removeTemporariesOnSignal() {
    static std::once_flag once;
    std::call_once(once, [] {
        sigset_t signals;
        sigemptyset(&signals);
        for (int signal_number : {SIGINT, SIGTERM, SIGHUP}) {
            struct sigaction old {};
            if (::sigaction(signal_number, nullptr, &old) == 0 && old.sa_handler == SIG_DFL)
                sigaddset(&signals, signal_number);
        }
        // Blocked here, so in every thread started from now on; the signal thread waits for them.
        ::pthread_sigmask(SIG_BLOCK, &signals, nullptr);
        std::thread thread(endOnSignal, signals);
        g_signal_thread = thread.native_handle();
        thread.detach();
        for (int signal_number : {SIGINT, SIGTERM, SIGHUP}) {
            if (!sigismember(&signals, signal_number)) continue;
            struct sigaction action {};
            action.sa_handler = forwardToSignalThread;
            sigemptyset(&action.sa_mask);
            ::sigaction(signal_number, &action, nullptr);
        }
    });
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
    const std::string held = absolutePath(tmp);
    beginWrite(held);
    try {
        write(tmp);
    } catch (const Error&) {
        endWrite();
        settle(held, {});
        throw;
    } catch (const std::exception& e) {
        endWrite();
        settle(held, {});
        throw RuntimeError(path.string() + ": write failed: " + e.what());
    }
    endWrite();
    if (current_group) {
        current_group->pending_.push_back({held, path});
        return;
    }
    settle(held, path);
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
