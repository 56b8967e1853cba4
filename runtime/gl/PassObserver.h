#pragma once
// What watches a frame's passes: the health check and content skip attach to the executor's frame
// as observers with hooks around each pass and each draw, so that the pass loop issues the passes
// and nothing else (a frame without them runs the loop with no observer at all). Hooks run in the
// order the observers were attached, at these points of each scheduled pass:
//   beforePass    before the pass's framebuffer is bound; any observer may say nothing of the
//                 pass is issued this frame (content skip knows its effect draws nothing)
//   beginDraw     each draw of the pass: its program in use, before its samplers are bound
//   samplerBound  each sampler bound for the draw, with the texture it reads
//   beforeDraw    the draw's bindings all made
//   afterDraws    the pass's draws done, before its mipmaps are made
//   afterPass     the pass done, issued or not

#include <cstddef>

#include "gl/GpuPass.h"

namespace rmfx {

// A scheduled pass as the frame issues it.
struct ObservedPass {
    size_t position = 0;           // in the schedule
    const GpuPass* scheduled = nullptr;
    unsigned writeTexture = 0;     // the texture the pass writes this frame
};

class PassObserver {
public:
    virtual ~PassObserver() = default;
    virtual void beginFrame(int frame, size_t passes) = 0;
    virtual bool beforePass(const ObservedPass&) { return true; }
    virtual void beginDraw(const ObservedPass&, const GpuPass& /*program*/) {}
    virtual void samplerBound(const SamplerSlot&, unsigned /*texture*/) {}
    virtual void beforeDraw(const ObservedPass&, const GpuPass& /*program*/) {}
    virtual void afterDraws(const ObservedPass&) {}
    virtual void afterPass(const ObservedPass&, bool /*issued*/) {}
    virtual void endFrame() = 0;
};

}  // namespace rmfx
