// Contiguous chunks of a loop on threads: see parallel_chunks.h.
#include "renderer/core/parallel_chunks.h"

#include <algorithm>
#include <exception>
#include <thread>
#include <vector>

namespace penumbra {

size_t parallelThreads() {
    static const size_t threads = std::clamp<size_t>(std::thread::hardware_concurrency(), 1, 16);
    return threads;
}

size_t parallelChunks(size_t n, size_t grain,
                      const std::function<void(size_t chunk, size_t begin, size_t end)>& work) {
    if (n == 0) return 0;
    grain = std::max<size_t>(grain, 1);
    const size_t size = std::max(grain, (n + parallelThreads() - 1) / parallelThreads());
    const size_t chunks = (n + size - 1) / size;
    std::vector<std::exception_ptr> failures(chunks);
    auto run = [&](size_t c) {
        try {
            work(c, c * size, std::min(n, (c + 1) * size));
        } catch (...) {
            failures[c] = std::current_exception();
        }
    };
    std::vector<std::thread> threads;
    for (size_t c = 1; c < chunks; ++c) threads.emplace_back(run, c);
    run(0);
    for (auto& t : threads) t.join();
    for (const auto& f : failures)
        if (f) std::rethrow_exception(f);
    return chunks;
}

}  // namespace penumbra
