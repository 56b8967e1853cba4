#pragma once
// How every headless run steps its frames (rmfx render, a sequence, replay, the Python module):
// frame i at time origin + i·dt with deltaTime dt, i < 0 being pre-roll frames before the first,
// each guarded by the frame budget's watchdog when there is one. One function, so that a frame of
// `rmfx render`, of a chunk of a sequence and of rmfx.Renderer runs at the very same float time.
// Needs the executor's GL context current.

#include <functional>
#include <optional>
#include <string>

#include "core/Diagnostic.h"
#include "core/FrameWatchdog.h"
#include "gl/GlExecutor.h"

namespace rmfx {

class FrameStepper {
public:
    // budgetSeconds 0: no watchdog (onBudget as FrameWatchdog's onTimeout).
    FrameStepper(float dt, double budgetSeconds = 0.0, std::function<void(const std::string&)> onBudget = {},
                 float origin = 0.0f);

    float dt() const { return dt_; }
    // The time of frame `index`: origin + index·dt in float, as the frame's rm_Time sees it.
    float time(long index) const { return origin_ + static_cast<float>(index) * dt_; }

    // Renders frame `index`; `label` names it in the watchdog's message ("frame 3 of W.xml"). With
    // a budget the frame's GPU work is waited for before the watchdog is disarmed. A failure when
    // the frame fails; its warnings either way.
    Result<void> step(GlExecutor& executor, long index, const std::string& label);
    // As step, then reads `target` back (which waits for the frame's GPU work) under the same
    // watchdog: a frame whose image is wanted.
    Result<Image> stepAndRead(GlExecutor& executor, long index, const std::string& label, const std::string& target);

private:
    float dt_;
    float origin_;
    std::optional<FrameWatchdog> watchdog_;
};

}  // namespace rmfx
