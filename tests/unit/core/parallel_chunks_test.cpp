// Contiguous chunks of a loop on threads: every index exactly once, chunks in order and at least
// the grain long (but the last), at most one a thread, and a chunk's exception rethrown.
#include <gtest/gtest.h>

#include <atomic>
#include <mutex>
#include <stdexcept>
#include <utility>
#include <vector>

#include "renderer/core/parallel_chunks.h"

namespace penumbra {
namespace {

TEST(ParallelChunks, CoverTheRangeOnceInOrderedChunks) {
    for (size_t n : {0u, 1u, 7u, 100u, 1000u, 100003u}) {
        for (size_t grain : {1u, 10u, 4096u}) {
            std::vector<std::atomic<int>> seen(n);
            std::mutex m;
            std::vector<std::pair<size_t, size_t>> ranges;
            const size_t chunks = parallelChunks(n, grain, [&](size_t c, size_t b, size_t e) {
                for (size_t i = b; i < e; ++i) ++seen[i];
                std::lock_guard lock(m);
                if (ranges.size() <= c) ranges.resize(c + 1);
                ranges[c] = {b, e};
            });
            ASSERT_EQ(ranges.size(), chunks);
            EXPECT_LE(chunks, parallelThreads());
            EXPECT_EQ(chunks == 0, n == 0);
            for (size_t i = 0; i < n; ++i) ASSERT_EQ(seen[i].load(), 1) << n << " " << i;
            for (size_t c = 0; c < chunks; ++c) {
                EXPECT_EQ(ranges[c].first, c == 0 ? 0 : ranges[c - 1].second);
                EXPECT_LT(ranges[c].first, ranges[c].second);
                if (c + 1 < chunks) {
                    EXPECT_GE(ranges[c].second - ranges[c].first, grain);
                }
            }
            if (chunks) {
                EXPECT_EQ(ranges.back().second, n);
            }
        }
    }
}

TEST(ParallelChunks, RethrowsAfterEveryChunkEnded) {
    std::atomic<size_t> ended{0};
    EXPECT_THROW(parallelChunks(1000, 1,
                                [&](size_t c, size_t, size_t) {
                                    ++ended;
                                    if (c == 0) throw std::runtime_error("chunk 0");
                                }),
                 std::runtime_error);
    EXPECT_EQ(ended.load(), std::min<size_t>(parallelThreads(), 1000));
}

}  // namespace
}  // namespace penumbra
