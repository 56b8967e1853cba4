#pragma once
// Owning handles for GL objects: move-only, the object is deleted when its handle dies or is reset.
// Every GL object rmfx creates lives in one of these; nothing else calls glDelete*. A handle must
// die while the context that made its object is current.

#include <utility>

namespace rmfx {

template <void (*Delete)(unsigned)>
class GlHandle {
public:
    GlHandle() = default;
    explicit GlHandle(unsigned name) : name_(name) {}
    ~GlHandle() { reset(); }
    GlHandle(GlHandle&& other) noexcept : name_(std::exchange(other.name_, 0)) {}
    GlHandle& operator=(GlHandle&& other) noexcept {
        if (this != &other) reset(std::exchange(other.name_, 0));
        return *this;
    }
    GlHandle(const GlHandle&) = delete;
    GlHandle& operator=(const GlHandle&) = delete;

    unsigned get() const { return name_; }
    explicit operator bool() const { return name_ != 0; }
    void reset(unsigned name = 0) {
        if (name_ != 0) Delete(name_);
        name_ = name;
    }

private:
    unsigned name_ = 0;
};

namespace gl {
void deleteTexture(unsigned name);
void deleteFramebuffer(unsigned name);
void deleteRenderbuffer(unsigned name);
void deleteProgram(unsigned name);
void deleteShader(unsigned name);
void deleteSampler(unsigned name);
void deleteQuery(unsigned name);
void deleteBuffer(unsigned name);
void deleteVertexArray(unsigned name);
}  // namespace gl

using TextureHandle = GlHandle<gl::deleteTexture>;
using FramebufferHandle = GlHandle<gl::deleteFramebuffer>;
using RenderbufferHandle = GlHandle<gl::deleteRenderbuffer>;
using ProgramHandle = GlHandle<gl::deleteProgram>;
using ShaderHandle = GlHandle<gl::deleteShader>;
using SamplerHandle = GlHandle<gl::deleteSampler>;
using QueryHandle = GlHandle<gl::deleteQuery>;
using BufferHandle = GlHandle<gl::deleteBuffer>;
using VertexArrayHandle = GlHandle<gl::deleteVertexArray>;

// A fence (glFenceSync) in the command stream: whether the GPU has passed it can be asked at any
// time without touching what came before it (a query an active conditional rendering uses, which
// NVIDIA forbids reading).
class FenceHandle {
public:
    FenceHandle() = default;
    ~FenceHandle() { reset(); }
    FenceHandle(FenceHandle&& other) noexcept : sync_(std::exchange(other.sync_, nullptr)) {}
    FenceHandle& operator=(FenceHandle&& other) noexcept {
        if (this != &other) {
            reset();
            sync_ = std::exchange(other.sync_, nullptr);
        }
        return *this;
    }
    FenceHandle(const FenceHandle&) = delete;
    FenceHandle& operator=(const FenceHandle&) = delete;

    explicit operator bool() const { return sync_ != nullptr; }
    void reset();
    void insert();          // a new fence after the commands issued so far (replacing this one)
    bool signalled() const; // the GPU has passed it; false without one. Never waits or flushes.
    void wait() const;      // until the GPU has passed it (flushing what is before it)

private:
    void* sync_ = nullptr;  // GLsync
};

// New objects (glCreate*), owned by the handle returned.
TextureHandle createTexture(unsigned target);
FramebufferHandle createFramebuffer();
RenderbufferHandle createRenderbuffer();
ProgramHandle createProgram();
ShaderHandle createShader(unsigned type);
SamplerHandle createSampler();
QueryHandle createQuery(unsigned target);
BufferHandle createBuffer();
VertexArrayHandle createVertexArray();

}  // namespace rmfx
