#include "gl/GlHandles.h"

#include <epoxy/gl.h>

namespace rmfx {
namespace gl {

void deleteTexture(unsigned name) { glDeleteTextures(1, &name); }
void deleteFramebuffer(unsigned name) { glDeleteFramebuffers(1, &name); }
void deleteRenderbuffer(unsigned name) { glDeleteRenderbuffers(1, &name); }
void deleteProgram(unsigned name) { glDeleteProgram(name); }
void deleteShader(unsigned name) { glDeleteShader(name); }
void deleteSampler(unsigned name) { glDeleteSamplers(1, &name); }
void deleteQuery(unsigned name) { glDeleteQueries(1, &name); }
void deleteBuffer(unsigned name) { glDeleteBuffers(1, &name); }
void deleteVertexArray(unsigned name) { glDeleteVertexArrays(1, &name); }

}  // namespace gl

void FenceHandle::reset() {
    if (sync_) glDeleteSync(static_cast<GLsync>(sync_));
    sync_ = nullptr;
}

void FenceHandle::insert() {
    reset();
    sync_ = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
}

bool FenceHandle::signalled() const {
    if (!sync_) return false;
    GLint status = GL_UNSIGNALED;
    glGetSynciv(static_cast<GLsync>(sync_), GL_SYNC_STATUS, 1, nullptr, &status);
    return status == GL_SIGNALED;
}

void FenceHandle::wait() const {
    if (!sync_) return;
    GLbitfield flags = GL_SYNC_FLUSH_COMMANDS_BIT;
    for (;;) {
        const GLenum r = glClientWaitSync(static_cast<GLsync>(sync_), flags, 1000000000);  // a second at a time
        if (r == GL_ALREADY_SIGNALED || r == GL_CONDITION_SATISFIED || r == GL_WAIT_FAILED) return;
        flags = 0;
    }
}

TextureHandle createTexture(unsigned target) {
    GLuint name = 0;
    glCreateTextures(target, 1, &name);
    return TextureHandle(name);
}

FramebufferHandle createFramebuffer() {
    GLuint name = 0;
    glCreateFramebuffers(1, &name);
    return FramebufferHandle(name);
}

RenderbufferHandle createRenderbuffer() {
    GLuint name = 0;
    glCreateRenderbuffers(1, &name);
    return RenderbufferHandle(name);
}

ProgramHandle createProgram() { return ProgramHandle(glCreateProgram()); }
ShaderHandle createShader(unsigned type) { return ShaderHandle(glCreateShader(type)); }

SamplerHandle createSampler() {
    GLuint name = 0;
    glCreateSamplers(1, &name);
    return SamplerHandle(name);
}

QueryHandle createQuery(unsigned target) {
    GLuint name = 0;
    glCreateQueries(target, 1, &name);
    return QueryHandle(name);
}

BufferHandle createBuffer() {
    GLuint name = 0;
    glCreateBuffers(1, &name);
    return BufferHandle(name);
}

VertexArrayHandle createVertexArray() {
    GLuint name = 0;
    glCreateVertexArrays(1, &name);
    return VertexArrayHandle(name);
}

}  // namespace rmfx
