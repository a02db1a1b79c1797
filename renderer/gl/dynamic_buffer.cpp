// Per-frame buffers: see dynamic_buffer.h.
#include "renderer/gl/dynamic_buffer.h"

#include <algorithm>

namespace penumbra::gl {

void DynamicBuffer::upload(std::span<const std::byte> bytes, GLenum target, GLuint binding,
                           size_t min_capacity) {
    const size_t needed = std::max({bytes.size(), min_capacity, size_t{16}});
    if (!buffer_ || needed > capacity_) {
        buffer_ = createBuffer(label_);
        glNamedBufferStorage(buffer_.id(), static_cast<GLsizeiptr>(needed), nullptr,
                             GL_DYNAMIC_STORAGE_BIT);
        capacity_ = needed;
    }
    if (!bytes.empty())
        glNamedBufferSubData(buffer_.id(), 0, static_cast<GLsizeiptr>(bytes.size()), bytes.data());
    glBindBufferBase(target, binding, buffer_.id());
}

}  // namespace penumbra::gl
