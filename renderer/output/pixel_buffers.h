// Pixel storage that a sequence's images hand on to the next: the channels (and half copies)
// of a frame already written are reused by a later frame's, so a long sequence writes into
// memory it touched before instead of allocating, faulting in and zeroing it every frame.
#pragma once

#include <cstddef>
#include <cstdint>
#include <mutex>
#include <vector>

namespace penumbra::output {

struct Image;

// What a new channel holds: zeros, or whatever its storage held (the caller writes every
// pixel before it is read).
enum class Fill { Zeros, Undefined };

// Thread-safe: several writers may take and give back at once.
class PixelBuffers {
public:
    // N floats: a buffer given back earlier (the smallest that holds N), else a new one.
    std::vector<float> take(size_t n, Fill fill);
    // Keeps IMAGE's channel buffers (at most kKept buffers in all), leaving it without channels.
    void recycle(Image&& image);
    // N half bit patterns (undefined), and their return.
    std::vector<std::uint16_t> takeHalves(size_t n);
    void give(std::vector<std::uint16_t>&& halves);

    static constexpr size_t kKept = 256;

private:
    std::mutex mutex_;
    std::vector<std::vector<float>> floats_;
    std::vector<std::vector<std::uint16_t>> halves_;
};

}  // namespace penumbra::output
