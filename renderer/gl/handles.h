// Move-only RAII wrappers for GL objects, each with a KHR_debug label, so a resource can never
// leak or be deleted twice and shows up by name in GL debuggers and error messages.
#pragma once

#include <glad/gl.h>

#include <string_view>
#include <utility>

namespace penumbra::gl {

// Deleters for each object kind.
struct TextureKind {
    static constexpr GLenum kLabel = GL_TEXTURE;
    static void destroy(GLuint id) { glDeleteTextures(1, &id); }
};
struct BufferKind {
    static constexpr GLenum kLabel = GL_BUFFER;
    static void destroy(GLuint id) { glDeleteBuffers(1, &id); }
};
struct FramebufferKind {
    static constexpr GLenum kLabel = GL_FRAMEBUFFER;
    static void destroy(GLuint id) { glDeleteFramebuffers(1, &id); }
};
struct VertexArrayKind {
    static constexpr GLenum kLabel = GL_VERTEX_ARRAY;
    static void destroy(GLuint id) { glDeleteVertexArrays(1, &id); }
};
struct ProgramKind {
    static constexpr GLenum kLabel = GL_PROGRAM;
    static void destroy(GLuint id) { glDeleteProgram(id); }
};
struct SamplerKind {
    static constexpr GLenum kLabel = GL_SAMPLER;
    static void destroy(GLuint id) { glDeleteSamplers(1, &id); }
};
struct QueryKind {
    static constexpr GLenum kLabel = GL_QUERY;
    static void destroy(GLuint id) { glDeleteQueries(1, &id); }
};

template <typename Kind>
class Handle {
public:
    Handle() = default;
    // Adopts ID (owned from now on) and labels it.
    Handle(GLuint id, std::string_view label) : id_(id) {
        if (id_ && !label.empty())
            glObjectLabel(Kind::kLabel, id_, static_cast<GLsizei>(label.size()), label.data());
    }
    ~Handle() { reset(); }
    Handle(const Handle&) = delete;
    Handle& operator=(const Handle&) = delete;
    Handle(Handle&& o) noexcept : id_(std::exchange(o.id_, 0)) {}
    Handle& operator=(Handle&& o) noexcept {
        if (this != &o) {
            reset();
            id_ = std::exchange(o.id_, 0);
        }
        return *this;
    }
    GLuint id() const { return id_; }
    explicit operator bool() const { return id_ != 0; }
    void reset() {
        if (id_) Kind::destroy(id_);
        id_ = 0;
    }

private:
    GLuint id_ = 0;
};

using Texture = Handle<TextureKind>;
using Buffer = Handle<BufferKind>;
using Framebuffer = Handle<FramebufferKind>;
using VertexArray = Handle<VertexArrayKind>;
using Program = Handle<ProgramKind>;
using Query = Handle<QueryKind>;
using Sampler = Handle<SamplerKind>;

// Creation helpers (DSA).
Texture createTexture(GLenum target, std::string_view label);
Buffer createBuffer(std::string_view label);
Sampler createSampler(std::string_view label);
Framebuffer createFramebuffer(std::string_view label);
VertexArray createVertexArray(std::string_view label);
Query createQuery(GLenum target, std::string_view label);

// A 2D texture with storage: FORMAT e.g. GL_RGBA32F, LEVELS mip levels, NEAREST (between
// levels too), clamp.
Texture createTexture2D(GLenum format, int width, int height, std::string_view label,
                        int levels = 1);
// A 2D array texture with storage, NEAREST, clamp.
Texture createTexture2DArray(GLenum format, int width, int height, int layers,
                             std::string_view label);

}  // namespace penumbra::gl
