#pragma once
// A headless OpenGL 4.5 core context through EGL: the surfaceless Mesa platform (llvmpipe, no
// display needed), else an EGL device (NVIDIA), else the default display. No window, no surface.

#include <memory>
#include <string>

#include "runtime/Result.h"

namespace rmfx {

class GlContext {
public:
    // Creates and makes current a context on the calling thread.
    static Result<std::unique_ptr<GlContext>> createHeadless();
    ~GlContext();
    GlContext(const GlContext&) = delete;
    GlContext& operator=(const GlContext&) = delete;

    void makeCurrent();
    const std::string& description() const { return description_; }  // "4.5 (Core Profile) Mesa …, llvmpipe … via EGL surfaceless"

private:
    GlContext() = default;
    void* display_ = nullptr;
    void* context_ = nullptr;
    std::string description_;
};

}  // namespace rmfx
