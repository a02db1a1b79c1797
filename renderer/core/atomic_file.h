// Atomic file writes: a temporary name beside the target, then rename, so a killed job never
// leaves a partial file under the final name. Shared by the EXR, PNG and JSON writers.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace penumbra {

// "<dir>/.<name>.<pid>.tmp": hidden, unique per process, in the target's folder (same device).
std::filesystem::path temporaryPathFor(const std::filesystem::path& path);

// Creates PATH's parent folders, calls WRITE(temporary path), then renames it to PATH.
// Something other than a regular file at PATH (a device, FIFO, folder or link) is not replaced.
// On any failure the temporary file is removed and RuntimeError names PATH.
void writeAtomically(const std::filesystem::path& path,
                     const std::function<void(const std::filesystem::path&)>& write);

// A frame's files as one unit: while a group is alive on this thread, writeAtomically writes
// each temporary file but defers its rename; commit() renames them in the order written (so
// the file written last appears last), and an uncommitted group removes its temporaries.
class AtomicGroup {
public:
    AtomicGroup();
    ~AtomicGroup();
    AtomicGroup(const AtomicGroup&) = delete;
    AtomicGroup& operator=(const AtomicGroup&) = delete;
    // Throws RuntimeError naming the file that could not be renamed (the rest are removed).
    void commit();

private:
    friend void writeAtomically(const std::filesystem::path&,
                                const std::function<void(const std::filesystem::path&)>&);
    struct Pending {
        std::string tmp;  // absolute, as held for the signal thread (removeTemporariesOnSignal)
        std::filesystem::path path;
    };
    std::vector<Pending> pending_;
    AtomicGroup* outer_;
};

// From now on SIGINT, SIGTERM and SIGHUP (where their action is the default, to end the
// process) first remove every temporary this process is writing or holding for a group's
// commit, then end it as before; a killed (SIGKILL) process leaves them for
// removeStaleTemporaries. The signals are blocked in the calling thread, and so in every thread
// it starts later, and a thread of their own waits for them: it lets the writes under way end
// (10 s at most), removes the temporaries and ends the process with no new one begun. Call it
// before starting threads that write; once is enough (later calls do nothing).
void removeTemporariesOnSignal();

// Removes the temporaries "<dir>/.<name>.<pid>.tmp" of PATH left by a process that is gone (its
// PID is not alive, or was started after the file was last written). Returns how many.
int removeStaleTemporaries(const std::filesystem::path& path);

// For checking outputs before any work: throws InputError("LABEL: PATH: ...") when
// writeAtomically would refuse to replace what is at PATH.
void checkOutputPath(const std::filesystem::path& path, const std::string& label);

// Writes TEXT to PATH atomically.
void writeFileAtomically(const std::filesystem::path& path, const std::string& text);

}  // namespace penumbra
