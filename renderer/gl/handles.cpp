// Creation helpers for the RAII GL handles.
#include "renderer/gl/handles.h"

namespace penumbra::gl {

Texture createTexture(GLenum target, std::string_view label) {
    GLuint id = 0;
    glCreateTextures(target, 1, &id);
    return Texture(id, label);
}

Sampler createSampler(std::string_view label) {
    GLuint id = 0;
    glCreateSamplers(1, &id);
    return Sampler(id, label);
}

Buffer createBuffer(std::string_view label) {
    GLuint id = 0;
    glCreateBuffers(1, &id);
    return Buffer(id, label);
}

Framebuffer createFramebuffer(std::string_view label) {
    GLuint id = 0;
    glCreateFramebuffers(1, &id);
    return Framebuffer(id, label);
}

VertexArray createVertexArray(std::string_view label) {
    GLuint id = 0;
    glCreateVertexArrays(1, &id);
    return VertexArray(id, label);
}

Query createQuery(GLenum target, std::string_view label) {
    GLuint id = 0;
    glCreateQueries(target, 1, &id);
    return Query(id, label);
}

namespace {
void setNearestClamp(GLuint id) {
    glTextureParameteri(id, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(id, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTextureParameteri(id, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(id, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}
}  // namespace

Texture createTexture2D(GLenum format, int width, int height, std::string_view label, int levels) {
    Texture t = createTexture(GL_TEXTURE_2D, label);
    glTextureStorage2D(t.id(), levels, format, width, height);
    setNearestClamp(t.id());
    if (levels > 1) glTextureParameteri(t.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
    return t;
}

Texture createTexture2DArray(GLenum format, int width, int height, int layers,
                             std::string_view label) {
    Texture t = createTexture(GL_TEXTURE_2D_ARRAY, label);
    glTextureStorage3D(t.id(), 1, format, width, height, layers);
    setNearestClamp(t.id());
    return t;
}

}  // namespace penumbra::gl
