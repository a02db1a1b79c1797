// Pixel-buffer readback: see readback_pool.h.
#include "renderer/passes/readback_pool.h"

#include <algorithm>

#include "renderer/core/error.h"

namespace penumbra::passes {

PendingRead::~PendingRead() {
    pool_->release(slot_);
}

void ReadbackPool::release(size_t slot) {
    std::lock_guard lock(mutex_);
    slots_[slot].busy = false;
}

std::unique_ptr<PendingRead> ReadbackPool::read(const gl::Texture& texture, int width, int height,
                                                GLenum format, GLenum type, size_t bytes_per_pixel,
                                                int layer) {
    const size_t bytes = static_cast<size_t>(width) * static_cast<size_t>(height) * bytes_per_pixel;
    size_t slot = 0;
    GLuint id = 0;
    void* mapped = nullptr;
    {
        std::lock_guard lock(mutex_);
        auto it = std::find_if(slots_.begin(), slots_.end(),
                               [&](const Slot& s) { return !s.busy && s.bytes == bytes; });
        if (it == slots_.end()) {
            constexpr GLbitfield kFlags =
                GL_MAP_READ_BIT | GL_MAP_PERSISTENT_BIT | GL_MAP_COHERENT_BIT;
            Slot s;
            glCreateBuffers(1, &id);
            s.buffer = gl::Buffer(id, "readback");
            glNamedBufferStorage(id, static_cast<GLsizeiptr>(bytes), nullptr, kFlags);
            s.mapped = glMapNamedBufferRange(id, 0, static_cast<GLsizeiptr>(bytes), kFlags);
            if (!s.mapped) throw RuntimeError("readback: cannot map a pixel buffer");
            s.bytes = bytes;
            slots_.push_back(std::move(s));
            it = slots_.end() - 1;
        }
        it->busy = true;
        slot = static_cast<size_t>(it - slots_.begin());
        id = it->buffer.id();
        mapped = it->mapped;
    }
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glBindBuffer(GL_PIXEL_PACK_BUFFER, id);
    glGetTextureSubImage(texture.id(), 0, 0, 0, std::max(layer, 0), width, height, 1, format, type,
                         static_cast<GLsizei>(bytes), nullptr);
    glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    return std::make_unique<PendingRead>(shared_from_this(), slot, mapped);
}

ReadbackFence ReadbackPool::fence() {
    ReadbackFence f(glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0));
    glFlush();  // the copies start now, behind the passes
    return f;
}

void ReadbackFence::wait(const char* where) {
    if (!sync_) return;
    GLenum status = GL_TIMEOUT_EXPIRED;
    while (status == GL_TIMEOUT_EXPIRED)
        status = glClientWaitSync(sync_, GL_SYNC_FLUSH_COMMANDS_BIT, 1000000000);  // 1 s
    glDeleteSync(std::exchange(sync_, nullptr));
    if (status == GL_WAIT_FAILED) throw RuntimeError(std::string(where) + ": readback failed");
}

}  // namespace penumbra::passes
