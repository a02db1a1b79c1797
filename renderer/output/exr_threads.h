// OpenEXR's global worker pool, given some threads once (ZIP compression and decompression are
// costly single-threaded); shared by the EXR reader and writer.
#pragma once

namespace penumbra::output {

void useExrWorkerThreads();

}  // namespace penumbra::output
