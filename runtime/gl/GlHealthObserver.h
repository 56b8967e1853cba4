#pragma once
// The health check (gl/GlHealthCheck.h) as an observer of a frame's passes (gl/PassObserver.h):
// it inspects what each pass wrote before the memory is written again, has the programs that
// count their own writes set up before they draw, and draws an inspection under the condition
// content skip drew the pass under.

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "gl/GlContentSkip.h"
#include "gl/GlHealthCheck.h"
#include "gl/PassObserver.h"

namespace rmfx {

class GlHealthObserver : public PassObserver {
public:
    // `inputLabel`: what the check calls a sampler's input (none: not one it looks at);
    // `keepsEarlierPixels`: the pass leaves what its target held where it does not draw, under
    // the current switches. `contentSkip` may be null.
    GlHealthObserver(GlHealthCheck& check, const GlContentSkip* contentSkip,
                     std::function<std::optional<std::string>(const SamplerSlot&)> inputLabel,
                     std::function<bool(const GpuPass&)> keepsEarlierPixels);

    void beginFrame(int frame, size_t passes) override { check_.beginFrame(frame, passes); }
    bool beforePass(const ObservedPass& pass) override;
    void beginDraw(const ObservedPass&, const GpuPass&) override { inputs_.clear(); }
    void samplerBound(const SamplerSlot& slot, unsigned texture) override;
    void beforeDraw(const ObservedPass& pass, const GpuPass& program) override;
    void afterPass(const ObservedPass& pass, bool issued) override;
    void endFrame() override { check_.endFrame(); }

private:
    GlHealthCheck& check_;
    const GlContentSkip* contentSkip_;
    std::function<std::optional<std::string>(const SamplerSlot&)> inputLabel_;
    std::function<bool(const GpuPass&)> keepsEarlierPixels_;
    std::vector<GlHealthCheck::Input> inputs_;  // the 2D inputs of the pass's last draw
};

}  // namespace rmfx
