// A buffer rewritten every frame: grows (reallocates) only when the data outgrows it, so
// steady-state frames upload without allocating; bound as SSBO or UBO by the caller's target.
#pragma once

#include <cstddef>
#include <span>
#include <string>

#include "renderer/gl/handles.h"

namespace penumbra::gl {

class DynamicBuffer {
public:
    explicit DynamicBuffer(std::string label) : label_(std::move(label)) {}
    // Uploads BYTES (at least MIN_CAPACITY bytes of storage) and binds the whole buffer to
    // index BINDING of TARGET (GL_SHADER_STORAGE_BUFFER or GL_UNIFORM_BUFFER).
    void upload(std::span<const std::byte> bytes, GLenum target, GLuint binding,
                size_t min_capacity = 0);
    template <typename T>
    void upload(std::span<const T> data, GLenum target, GLuint binding, size_t min_capacity = 0) {
        upload(std::as_bytes(data), target, binding, min_capacity);
    }

    // The buffer, to bind again after other passes used its binding.
    GLuint id() const { return buffer_.id(); }

private:
    std::string label_;
    Buffer buffer_;
    size_t capacity_ = 0;
};

}  // namespace penumbra::gl
