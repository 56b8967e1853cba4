#pragma once
// The GL memory of a TargetPlan: a texture and framebuffer per resource (two for a target read with
// frame="previous"), a depth renderbuffer where a pass needs one. Targets whose lifetimes do not
// overlap point to the same resource. Needs a current GL context.

#include <memory>
#include <string>
#include <vector>

#include "core/Result.h"
#include "gl/GlHandles.h"
#include "graph/TargetPlan.h"

namespace rmfx {

struct GpuResource {
    TargetResource spec;
    TextureHandle textures[2];
    FramebufferHandle framebuffers[2];
    RenderbufferHandle depth;
    int front = 0;  // buffer with the last finished frame's contents

    int writeBuffer() const { return spec.history ? 1 - front : 0; }
};

struct GpuTarget {
    std::string name;
    const RenderTarget* spec = nullptr;  // null for the implicit output
    GpuResource* resource = nullptr;     // null when the plan does not allocate it
    bool writtenThisFrame = false;
    SourceLocation where;
};

class GlRenderTargets {
public:
    // Replaces the memory by the plan's (every target back to its initial value), allocated before
    // the old memory is freed: on an error the old memory stays in use. The targets themselves are
    // made on the first call and stay: passes point to them. Errors name the target whose
    // framebuffer is incomplete or whose allocation raised a GL error.
    Result<void> allocate(const TargetPlan& plan);

    GpuTarget* find(const std::string& name) const;
    const std::vector<std::unique_ptr<GpuTarget>>& targets() const { return targets_; }

    void startFrame();
    // Double-buffered targets written this frame: next frame writes the other buffer, and
    // frame="previous" reads this one.
    void finishFrame();

private:
    std::vector<std::unique_ptr<GpuResource>> resources_;
    std::vector<std::unique_ptr<GpuTarget>> targets_;
};

}  // namespace rmfx
