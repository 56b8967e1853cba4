#include "gl/GlErrors.h"

#include <cstdio>

#include <epoxy/gl.h>

namespace rmfx {

std::vector<std::string> drainGlErrors() {
    std::vector<std::string> errors;
    for (GLenum e; (e = glGetError()) != GL_NO_ERROR;) errors.push_back(describeGlError(e));
    return errors;
}

std::string firstGlError() {
    std::vector<std::string> errors = drainGlErrors();
    return errors.empty() ? std::string() : errors.front();
}

std::string describeGlError(unsigned error) {
    switch (error) {
        case GL_INVALID_ENUM: return "GL_INVALID_ENUM";
        case GL_INVALID_VALUE: return "GL_INVALID_VALUE";
        case GL_INVALID_OPERATION: return "GL_INVALID_OPERATION";
        case GL_INVALID_FRAMEBUFFER_OPERATION: return "GL_INVALID_FRAMEBUFFER_OPERATION";
        case GL_OUT_OF_MEMORY: return "GL_OUT_OF_MEMORY";
        default: {
            char buffer[32];
            std::snprintf(buffer, sizeof buffer, "GL error 0x%04x", error);
            return buffer;
        }
    }
}

std::string describeFramebufferStatus(unsigned status) {
    switch (status) {
        case GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT: return "incomplete attachment";
        case GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT: return "no attachment";
        case GL_FRAMEBUFFER_UNSUPPORTED: return "format combination unsupported by the driver";
        default: return "status 0x" + std::to_string(status);
    }
}

}  // namespace rmfx
