#include "gl/GlDebugOutput.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>

#include <epoxy/gl.h>

namespace rmfx {
namespace {

void GLAPIENTRY writeMessage(GLenum, GLenum type, GLuint id, GLenum severity, GLsizei length, const GLchar* message,
                             const void*) {
    if (type != GL_DEBUG_TYPE_ERROR && severity != GL_DEBUG_SEVERITY_HIGH && severity != GL_DEBUG_SEVERITY_MEDIUM) return;
    std::fprintf(stderr, "rmfx: GL debug (id %u): %.*s\n", id, static_cast<int>(length < 0 ? std::strlen(message) : length),
                 message);
}

}  // namespace

bool glDebugOutputAsked() {
    const char* value = std::getenv("RMFX_GL_DEBUG");
    return value && *value && std::strcmp(value, "0") != 0;
}

void installGlDebugOutput() {
    if (!epoxy_has_gl_extension("GL_KHR_debug") && epoxy_gl_version() < 43) return;
    glEnable(GL_DEBUG_OUTPUT);
    glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);  // the message comes from inside the call that raised it
    glDebugMessageCallback(writeMessage, nullptr);
}

}  // namespace rmfx
