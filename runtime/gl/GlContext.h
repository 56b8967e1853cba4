#pragma once
// A headless OpenGL 4.5 context (core, or compatibility for legacy GLSL) through EGL: the surfaceless Mesa platform (llvmpipe, no
// display needed), else an EGL device (NVIDIA), else the default display. No window, no surface.

#include <memory>
#include <string>

#include "core/Result.h"
#include "model/GlProfile.h"

namespace rmfx {

class GlContext {
public:
    // Creates and makes current a context on the calling thread.
    // Compatibility: "4.5 (Compatibility Profile)", with the fixed-function matrices, lights and
    // vertex arrays that legacy GLSL reads (Workspace::profile).
    static Result<std::unique_ptr<GlContext>> createHeadless(GlProfile profile = GlProfile::Core);
    // Initialises the display createHeadless will try first, which loads the driver, so that a
    // createHeadless later (on any thread) finds it ready. Does nothing where none initialises.
    static void prepareHeadlessDisplay();
    ~GlContext();
    GlContext(const GlContext&) = delete;
    GlContext& operator=(const GlContext&) = delete;

    void makeCurrent();
    const std::string& description() const { return description_; }
    GlProfile profile() const { return profile_; }  // "4.5 (Core Profile) Mesa …, llvmpipe … via EGL surfaceless"

private:
    GlContext() = default;
    void* display_ = nullptr;
    void* context_ = nullptr;
    std::string description_;
    GlProfile profile_ = GlProfile::Core;
};

}  // namespace rmfx
