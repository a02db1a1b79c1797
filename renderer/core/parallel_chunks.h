// A loop over [0, n) split into contiguous chunks, each run on a thread of its own (the
// caller's thread runs the first): CPU work between GPU passes that a many-core host spreads.
#pragma once

#include <cstddef>
#include <functional>

namespace penumbra {

// Calls WORK(chunk, begin, end) for consecutive chunks covering [0, N), each at least GRAIN long
// (but the last), on up to `parallelThreads()` threads at once, and returns when all are done;
// returns the number of chunks (0 when N is 0). An exception from WORK is rethrown (the
// first chunk's first) after every chunk has ended.
size_t parallelChunks(size_t n, size_t grain,
                      const std::function<void(size_t chunk, size_t begin, size_t end)>& work);

// The chunks' threads at most: the cores, at most 16.
size_t parallelThreads();

}  // namespace penumbra
