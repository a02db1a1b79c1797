// Readback through pixel buffer objects: a texture's copy to the CPU is queued behind the
// frame's passes into a persistently mapped GL_PIXEL_PACK_BUFFER and a fence, and read later
// (on any thread, once the GL thread has waited for the fence), so the copy overlaps other
// work and the CPU side never waits on glGetTextureSubImage. Buffers are reused across frames.
#pragma once

#include <cstddef>
#include <memory>
#include <mutex>
#include <utility>
#include <vector>

#include "renderer/gl/handles.h"

namespace penumbra::passes {

class ReadbackPool;

// A fence behind queued copies: move-only, waited for (and deleted) once, on the GL thread.
class ReadbackFence {
public:
    ReadbackFence() = default;
    explicit ReadbackFence(GLsync sync) : sync_(sync) {}
    ~ReadbackFence() {
        if (sync_) glDeleteSync(sync_);  // never waited for (a frame given up)
    }
    ReadbackFence(ReadbackFence&& o) noexcept : sync_(std::exchange(o.sync_, nullptr)) {}
    ReadbackFence& operator=(ReadbackFence&& o) noexcept {
        std::swap(sync_, o.sync_);
        return *this;
    }
    ReadbackFence(const ReadbackFence&) = delete;
    ReadbackFence& operator=(const ReadbackFence&) = delete;
    bool pending() const { return sync_ != nullptr; }
    // Waits for the copies; throws RuntimeError naming WHERE if the wait fails.
    void wait(const char* where);

private:
    GLsync sync_ = nullptr;
};

// One texture read into a pool buffer: its bytes (GL's row order, bottom row first) are valid
// once the pool's fence for them has been waited on; the buffer returns to the pool when the
// read is destroyed (on any thread).
class PendingRead {
public:
    PendingRead(std::shared_ptr<ReadbackPool> pool, size_t slot, const void* data)
        : pool_(std::move(pool)), slot_(slot), data_(data) {}
    ~PendingRead();
    PendingRead(const PendingRead&) = delete;
    PendingRead& operator=(const PendingRead&) = delete;
    template <typename T>
    const T* as() const {
        return static_cast<const T*>(data_);
    }

private:
    std::shared_ptr<ReadbackPool> pool_;
    size_t slot_;
    const void* data_;
};

// Owned by the GL thread, which must destroy it after every read it handed out (the buffers
// are deleted with it).
class ReadbackPool : public std::enable_shared_from_this<ReadbackPool> {
public:
    static std::shared_ptr<ReadbackPool> create() {
        return std::shared_ptr<ReadbackPool>(new ReadbackPool());
    }
    // Queues the copy of level 0 (LAYER of an array texture, -1 for 2D) as FORMAT/TYPE with
    // BYTES_PER_PIXEL bytes a pixel. GL thread only.
    std::unique_ptr<PendingRead> read(const gl::Texture& texture, int width, int height,
                                      GLenum format, GLenum type, size_t bytes_per_pixel,
                                      int layer = -1);
    // A fence behind every read queued so far; GL thread only.
    ReadbackFence fence();

private:
    ReadbackPool() = default;
    friend class PendingRead;
    void release(size_t slot);
    struct Slot {
        gl::Buffer buffer;
        size_t bytes = 0;
        void* mapped = nullptr;
        bool busy = false;
    };
    std::mutex mutex_;  // busy flags: reads are released on the writer's thread
    std::vector<Slot> slots_;
};

}  // namespace penumbra::passes
