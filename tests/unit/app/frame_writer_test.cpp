// The render job's frame writer: several workers write frames at once, no more frames than
// workers are handed over and unwritten, outcomes come back in the order handed over whatever
// order the frames finish in, a RuntimeError is a failed frame and anything else is rethrown;
// the worker count from PENUMBRA_WRITER_THREADS or the cores.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cstdlib>
#include <stdexcept>
#include <thread>

#include "renderer/app/render_job_writer.h"
#include "renderer/core/error.h"

namespace penumbra::app {
namespace {

TEST(FrameWriter, SeveralWorkersWriteAtOnceWithinTheirBound) {
    constexpr int kWorkers = 3;
    std::atomic<int> running{0}, most{0}, done{0};
    {
        FrameWriter writer(kWorkers, false);
        for (int f = 1; f <= 12; ++f)
            writer.submit(f, [&, f] {
                const int now = ++running;
                int seen = most.load();
                while (now > seen && !most.compare_exchange_weak(seen, now)) {
                }
                // Later frames finish first: the outcomes must still come back in order.
                std::this_thread::sleep_for(std::chrono::milliseconds(5 * (13 - f) % 40 + 5));
                --running;
                ++done;
            });
        writer.finish();
        EXPECT_EQ(done.load(), 12);
        const std::vector<WriteOutcome> outcomes = writer.takeOutcomes();
        ASSERT_EQ(outcomes.size(), 12u);
        for (int f = 1; f <= 12; ++f) {
            EXPECT_EQ(outcomes[static_cast<size_t>(f - 1)].frame, f);
            EXPECT_TRUE(outcomes[static_cast<size_t>(f - 1)].message.empty());
        }
    }
    EXPECT_GT(most.load(), 1);  // they overlapped
    EXPECT_LE(most.load(), kWorkers);
}

TEST(FrameWriter, ABoundOfUnwrittenFramesBlocksTheCaller) {
    std::atomic<bool> release{false};
    std::atomic<int> started{0};
    FrameWriter writer(2, false);
    auto blocked = [&] {
        ++started;
        while (!release) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    };
    writer.submit(1, blocked);
    writer.submit(2, blocked);
    std::atomic<bool> third_in{false};
    std::thread caller([&] {
        writer.submit(3, [] {});
        third_in = true;
    });
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    EXPECT_FALSE(third_in.load());  // two unwritten: the third waits
    release = true;
    caller.join();
    writer.finish();
    EXPECT_EQ(writer.takeOutcomes().size(), 3u);
}

TEST(FrameWriter, FailuresAreOutcomesOrRethrown) {
    FrameWriter writer(2, false);
    writer.submit(4, [] { throw RuntimeError("disk full"); });
    writer.submit(5, [] {});
    writer.finish();
    const auto outcomes = writer.takeOutcomes();
    ASSERT_EQ(outcomes.size(), 2u);
    EXPECT_EQ(outcomes[0].frame, 4);
    EXPECT_EQ(outcomes[0].message, "disk full");
    EXPECT_TRUE(outcomes[1].message.empty());
    writer.submit(6, [] { throw std::logic_error("a bug"); });
    writer.finish();
    EXPECT_THROW(writer.takeOutcomes(), std::logic_error);
}

TEST(FrameWriter, SerialWritesInSubmit) {
    FrameWriter writer(4, true);
    bool ran = false;
    writer.submit(1, [&] { ran = true; });
    EXPECT_TRUE(ran);
    EXPECT_EQ(writer.takeOutcomes().size(), 1u);
}

TEST(FrameWriter, WorkersFromTheCoresOrTheEnvironment) {
    ::unsetenv("PENUMBRA_WRITER_THREADS");
    EXPECT_EQ(FrameWriter::workersFor(1), 2);
    EXPECT_EQ(FrameWriter::workersFor(2), 2);
    EXPECT_EQ(FrameWriter::workersFor(8), 2);
    EXPECT_EQ(FrameWriter::workersFor(16), 4);
    EXPECT_EQ(FrameWriter::workersFor(128), 4);
    ::setenv("PENUMBRA_WRITER_THREADS", "3", 1);
    EXPECT_EQ(FrameWriter::workersFor(2), 3);
    for (const char* bad : {"0", "17", "two", "", "-1", "100"}) {
        ::setenv("PENUMBRA_WRITER_THREADS", bad, 1);
        EXPECT_THROW(FrameWriter::workersFor(16), InputError) << bad;
    }
    ::unsetenv("PENUMBRA_WRITER_THREADS");
}

}  // namespace
}  // namespace penumbra::app
