// The render job's frame writer: see render_job_writer.h.
#include "renderer/app/render_job_writer.h"

#include <cstdlib>
#include <cstring>
#include <utility>

#include "renderer/core/error.h"

namespace penumbra::app {

FrameWriter::FrameWriter(int depth, bool serial) : depth_(depth < 1 ? 1 : depth) {
    if (!serial) worker_ = std::thread([this] { run(); });
}

FrameWriter::~FrameWriter() {
    if (!worker_.joinable()) return;
    {
        std::lock_guard lock(mutex_);
        stopping_ = true;
    }
    changed_.notify_all();
    worker_.join();  // the worker empties the queue first
}

bool FrameWriter::serialRequested() {
    const char* v = std::getenv("PENUMBRA_SERIAL_WRITES");
    return v && std::strcmp(v, "1") == 0;
}

void FrameWriter::record(int frame, const std::function<void()>& work) {
    WriteOutcome outcome{frame, {}};
    std::exception_ptr failure;
    try {
        work();
    } catch (const RuntimeError& e) {
        outcome.message = e.what();
    } catch (...) {
        failure = std::current_exception();
        outcome.message = "write failed";
    }
    std::lock_guard lock(mutex_);
    outcomes_.push_back(std::move(outcome));
    if (failure && !failure_) failure_ = failure;
}

void FrameWriter::submit(int frame, std::function<void()> work) {
    if (!worker_.joinable()) {
        record(frame, work);
        return;
    }
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [&] { return unwritten_ < depth_; });
    queue_.push_back({frame, std::move(work)});
    ++unwritten_;
    changed_.notify_all();
}

void FrameWriter::run() {
    std::unique_lock lock(mutex_);
    for (;;) {
        changed_.wait(lock, [&] { return stopping_ || !queue_.empty(); });
        if (queue_.empty()) return;  // stopping, and nothing left
        Task task = std::move(queue_.front());
        queue_.pop_front();
        lock.unlock();
        record(task.frame, task.work);
        task.work = nullptr;  // the frame's image is freed before the next is taken
        lock.lock();
        --unwritten_;
        changed_.notify_all();
    }
}

std::vector<WriteOutcome> FrameWriter::takeOutcomes() {
    std::lock_guard lock(mutex_);
    if (failure_) std::rethrow_exception(std::exchange(failure_, nullptr));
    return std::exchange(outcomes_, {});
}

void FrameWriter::finish() {
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [&] { return unwritten_ == 0; });
}

}  // namespace penumbra::app
