// Writes a render job's frames while the next ones render: each frame's finishing work (the
// image assembled from its readback, EXR encoding through OpenEXR's thread pool, the files
// written under temporary names and renamed) runs on a worker thread, one frame a worker (one
// worker by default, more on a machine with many cores), with at most one frame a worker
// handed over and not yet written. PENUMBRA_SERIAL_WRITES=1 runs the same work on the caller's
// thread instead (same bytes; for tests and comparisons).
#pragma once

#include <condition_variable>
#include <deque>
#include <exception>
#include <functional>
#include <mutex>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace penumbra::app {

// How one handed-over frame ended: MESSAGE empty when its files are written.
struct WriteOutcome {
    int frame = 0;
    std::string message;  // a RuntimeError's message
};

class FrameWriter {
public:
    // WORKERS threads (at least 1) write at most one frame each at once, and as many frames
    // may be handed over and unwritten; SERIAL writes each frame in submit() instead.
    FrameWriter(int workers, bool serial);
    // Writes what was handed over, then stops the workers.
    ~FrameWriter();
    FrameWriter(const FrameWriter&) = delete;
    FrameWriter& operator=(const FrameWriter&) = delete;

    // Hands over FRAME's WORK (throws RuntimeError on failure); blocks while DEPTH frames are
    // unwritten (the workers' number).
    void submit(int frame, std::function<void()> work);
    // Outcomes of the frames written since the last call, in the order handed over. An
    // exception other than RuntimeError thrown by a frame's work is rethrown here.
    std::vector<WriteOutcome> takeOutcomes();
    // Waits until every handed-over frame is written; then takeOutcomes() holds them all.
    void finish();

    // Whether the environment asks for serial writes (PENUMBRA_SERIAL_WRITES set to 1).
    static bool serialRequested();
    // The number of workers: PENUMBRA_WRITER_THREADS (1-16) when set, else one for every 4
    // cores, 2 to 4 (a frame's encoding already runs on OpenEXR's threads, one a core; on 2
    // cores a second writer still overlaps one frame's file writes with another's encoding).
    static int workersFor(unsigned cores);

private:
    struct Task {
        int frame;
        long order;  // handed over as the ORDER-th
        std::function<void()> work;
    };
    void run();
    void record(const Task& task);

    const int depth_;
    std::mutex mutex_;
    std::condition_variable changed_;
    std::deque<Task> queue_;
    int unwritten_ = 0;  // queued or being written
    long submitted_ = 0;
    bool stopping_ = false;
    std::vector<std::pair<long, WriteOutcome>> outcomes_;  // with their tasks' order
    std::exception_ptr failure_;        // an unexpected exception from a frame's work
    std::vector<std::thread> workers_;  // none when serial
};

}  // namespace penumbra::app
