// KHR_debug callback and error checks: see debug.h.
#include "renderer/gl/debug.h"

#include <glad/gl.h>

#include <cstdio>
#include <cstring>
#include <mutex>

#include "renderer/core/error.h"

namespace penumbra::gl {
namespace {

std::mutex g_mutex;
std::string g_firstError;
bool g_verbose = false;

void GLAPIENTRY onDebugMessage(GLenum source, GLenum type, GLuint id, GLenum severity,
                               GLsizei length, const GLchar* message, const void* /*user*/) {
    (void)source;
    (void)id;
    std::string text(message, length > 0 ? static_cast<size_t>(length) : std::strlen(message));
    if (g_verbose)
        std::fprintf(stderr, "penumbra: gl-debug: [type 0x%x severity 0x%x] %s\n", type, severity,
                     text.c_str());
    if (type == GL_DEBUG_TYPE_ERROR) {
        std::lock_guard<std::mutex> lock(g_mutex);
        if (g_firstError.empty()) g_firstError = text;
    }
}

}  // namespace

void enableDebugOutput(bool verbose) {
    g_verbose = verbose;
    glEnable(GL_DEBUG_OUTPUT);
    glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
    glDebugMessageCallback(onDebugMessage, nullptr);
    // Everything when verbose; otherwise only errors reach the callback.
    glDebugMessageControl(GL_DONT_CARE, GL_DONT_CARE, GL_DONT_CARE, 0, nullptr,
                          verbose ? GL_TRUE : GL_FALSE);
    glDebugMessageControl(GL_DONT_CARE, GL_DEBUG_TYPE_ERROR, GL_DONT_CARE, 0, nullptr, GL_TRUE);
    glDebugMessageControl(GL_DEBUG_SOURCE_APPLICATION, GL_DEBUG_TYPE_PUSH_GROUP, GL_DONT_CARE, 0,
                          nullptr, GL_FALSE);
    glDebugMessageControl(GL_DEBUG_SOURCE_APPLICATION, GL_DEBUG_TYPE_POP_GROUP, GL_DONT_CARE, 0,
                          nullptr, GL_FALSE);
}

void checkErrors(std::string_view where) {
    std::string message;
    {
        std::lock_guard<std::mutex> lock(g_mutex);
        message.swap(g_firstError);
    }
    GLenum e = glGetError();
    if (message.empty() && e != GL_NO_ERROR) {
        char buf[48];
        std::snprintf(buf, sizeof buf, "glGetError 0x%04x", e);
        message = buf;
    }
    while (e != GL_NO_ERROR) e = glGetError();
    if (!message.empty()) throw RuntimeError(std::string(where) + ": GL error: " + message);
}

DebugGroup::DebugGroup(std::string_view name) {
    glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, static_cast<GLsizei>(name.size()),
                     name.data());
}

DebugGroup::~DebugGroup() {
    glPopDebugGroup();
}

}  // namespace penumbra::gl
