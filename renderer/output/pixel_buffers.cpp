// Pixel storage reused across a sequence's images: see pixel_buffers.h.
#include "renderer/output/pixel_buffers.h"

#include <utility>

#include "renderer/output/image.h"

namespace penumbra::output {

namespace {

// The smallest of FREE that holds N, moved out of it, or an empty vector.
template <typename T>
std::vector<T> takeSmallest(std::vector<std::vector<T>>& free, size_t n) {
    auto best = free.end();
    for (auto it = free.begin(); it != free.end(); ++it)
        if (it->capacity() >= n && (best == free.end() || it->capacity() < best->capacity()))
            best = it;
    if (best == free.end()) return {};
    std::vector<T> v = std::move(*best);
    free.erase(best);
    return v;
}

}  // namespace

std::vector<float> PixelBuffers::take(size_t n, Fill fill) {
    std::vector<float> pixels;
    {
        std::lock_guard lock(mutex_);
        pixels = takeSmallest(floats_, n);
    }
    if (fill == Fill::Zeros)
        pixels.assign(n, 0.0f);
    else
        pixels.resize(n);  // a buffer of the same size keeps its contents: nothing written
    return pixels;
}

void PixelBuffers::recycle(Image&& image) {
    std::lock_guard lock(mutex_);
    for (auto& c : image.channels)
        if (floats_.size() + halves_.size() < kKept && c.pixels.capacity() > 0)
            floats_.push_back(std::move(c.pixels));
    image.channels.clear();
}

std::vector<std::uint16_t> PixelBuffers::takeHalves(size_t n) {
    std::vector<std::uint16_t> halves;
    {
        std::lock_guard lock(mutex_);
        halves = takeSmallest(halves_, n);
    }
    halves.resize(n);
    return halves;
}

void PixelBuffers::give(std::vector<std::uint16_t>&& halves) {
    std::lock_guard lock(mutex_);
    if (floats_.size() + halves_.size() < kKept && halves.capacity() > 0)
        halves_.push_back(std::move(halves));
}

}  // namespace penumbra::output
