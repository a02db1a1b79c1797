// OpenEXR's worker pool, set up once: see exr_threads.h.
#include "renderer/output/exr_threads.h"

#include <OpenEXR/ImfThreading.h>

#include <algorithm>
#include <mutex>
#include <thread>

namespace penumbra::output {

void useExrWorkerThreads() {
    static std::once_flag once;
    std::call_once(once, [] {
        // A thread a core: a sequence's writer threads (render_job_writer.h) share the pool, and
        // on a GPU host the encoding of their frames is the work there is to spread.
        unsigned n = std::thread::hardware_concurrency();
        if (Imf::globalThreadCount() == 0 && n > 1)
            Imf::setGlobalThreadCount(static_cast<int>(std::min(n, 32u)));
    });
}

}  // namespace penumbra::output
