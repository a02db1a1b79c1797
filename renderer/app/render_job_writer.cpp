// The render job's frame writer: see render_job_writer.h.
#include "renderer/app/render_job_writer.h"

#include <algorithm>
#include <charconv>
#include <cstdlib>
#include <cstring>
#include <string>
#include <utility>

#include "renderer/core/error.h"

namespace penumbra::app {

FrameWriter::FrameWriter(int workers, bool serial) : depth_(std::max(workers, 1)) {
    if (serial) return;
    for (int i = 0; i < depth_; ++i) workers_.emplace_back([this] { run(); });
}

FrameWriter::~FrameWriter() {
    if (workers_.empty()) return;
    {
        std::lock_guard lock(mutex_);
        stopping_ = true;
    }
    changed_.notify_all();
    for (auto& w : workers_) w.join();  // the workers empty the queue first
}

bool FrameWriter::serialRequested() {
    const char* v = std::getenv("PENUMBRA_SERIAL_WRITES");
    return v && std::strcmp(v, "1") == 0;
}

int FrameWriter::workersFor(unsigned cores) {
    if (const char* v = std::getenv("PENUMBRA_WRITER_THREADS")) {
        const char* end = v + std::strlen(v);
        int n = 0;
        const auto [stop, ec] = std::from_chars(v, end, n);
        if (ec == std::errc() && stop == end && n >= 1 && n <= 16) return n;
        throw InputError("PENUMBRA_WRITER_THREADS: '" + std::string(v) +
                         "' is not a number from 1 to 16");
    }
    return std::clamp(static_cast<int>(cores / 4), 2, 4);
}

void FrameWriter::record(const Task& task) {
    WriteOutcome outcome{task.frame, {}};
    std::exception_ptr failure;
    try {
        task.work();
    } catch (const RuntimeError& e) {
        outcome.message = e.what();
    } catch (...) {
        failure = std::current_exception();
        outcome.message = "write failed";
    }
    std::lock_guard lock(mutex_);
    outcomes_.emplace_back(task.order, std::move(outcome));
    if (failure && !failure_) failure_ = failure;
}

void FrameWriter::submit(int frame, std::function<void()> work) {
    std::unique_lock lock(mutex_);
    Task task{frame, submitted_++, std::move(work)};
    if (workers_.empty()) {
        lock.unlock();
        record(task);
        return;
    }
    changed_.wait(lock, [&] { return unwritten_ < depth_; });
    queue_.push_back(std::move(task));
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
        record(task);
        task.work = nullptr;  // the frame's image is freed before the next is taken
        lock.lock();
        --unwritten_;
        changed_.notify_all();
    }
}

std::vector<WriteOutcome> FrameWriter::takeOutcomes() {
    std::lock_guard lock(mutex_);
    if (failure_) std::rethrow_exception(std::exchange(failure_, nullptr));
    std::sort(outcomes_.begin(), outcomes_.end(),
              [](const auto& a, const auto& b) { return a.first < b.first; });
    std::vector<WriteOutcome> out;
    for (auto& o : outcomes_) out.push_back(std::move(o.second));
    outcomes_.clear();
    return out;
}

void FrameWriter::finish() {
    std::unique_lock lock(mutex_);
    changed_.wait(lock, [&] { return unwritten_ == 0; });
}

}  // namespace penumbra::app
