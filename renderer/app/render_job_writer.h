// Writes a render job's frames while the next ones render: each frame's finishing work (the
// image assembled from its readback, EXR encoding through OpenEXR's thread pool, the files
// written under temporary names and renamed) runs on one worker thread, with at most a bounded
// number of frames handed over and not yet written. PENUMBRA_SERIAL_WRITES=1 runs the same work
// on the caller's thread instead (same bytes; for tests and comparisons).
#pragma once

#include <condition_variable>
#include <deque>
#include <exception>
#include <functional>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace penumbra::app {

// How one handed-over frame ended: MESSAGE empty when its files are written.
struct WriteOutcome {
    int frame = 0;
    std::string message;  // a RuntimeError's message
};

class FrameWriter {
public:
    // DEPTH frames may be handed over and unwritten at once (at least 1); SERIAL writes each
    // frame in submit() instead.
    FrameWriter(int depth, bool serial);
    // Writes what was handed over, then stops the worker.
    ~FrameWriter();
    FrameWriter(const FrameWriter&) = delete;
    FrameWriter& operator=(const FrameWriter&) = delete;

    // Hands over FRAME's WORK (throws RuntimeError on failure); blocks while DEPTH frames are
    // unwritten.
    void submit(int frame, std::function<void()> work);
    // Outcomes of the frames written since the last call, in the order handed over. An
    // exception other than RuntimeError thrown by a frame's work is rethrown here.
    std::vector<WriteOutcome> takeOutcomes();
    // Waits until every handed-over frame is written; then takeOutcomes() holds them all.
    void finish();

    // Whether the environment asks for serial writes (PENUMBRA_SERIAL_WRITES set to 1).
    static bool serialRequested();

private:
    struct Task {
        int frame;
        std::function<void()> work;
    };
    void run();
    void record(int frame, const std::function<void()>& work);

    const int depth_;
    std::mutex mutex_;
    std::condition_variable changed_;
    std::deque<Task> queue_;
    int unwritten_ = 0;  // queued or being written
    bool stopping_ = false;
    std::vector<WriteOutcome> outcomes_;
    std::exception_ptr failure_;  // an unexpected exception from a frame's work
    std::thread worker_;          // not started when serial
};

}  // namespace penumbra::app
