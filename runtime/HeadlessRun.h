#pragma once
// Renders a workspace for a fixed number of frames with a fixed time step: what `rmfx render`,
// replay tests and the GL tests all do. Needs a current GL context.

#include <functional>
#include <memory>
#include <string>

#include <glm/vec2.hpp>

#include "runtime/Diagnostic.h"
#include "runtime/GlExecutor.h"
#include "runtime/Workspace.h"

namespace rmfx {

struct RunSettings {
    RunSettings(glm::ivec2 size = glm::ivec2(0), int frames = 1, float deltaTime = 1.0f / 60.0f)
        : size(size), frames(frames), deltaTime(deltaTime) {}

    glm::ivec2 size;  // 0: the workspace's size
    int frames;
    float deltaTime;
    // Seconds a frame may take, GPU work included, before the run is stopped (FrameWatchdog:
    // the process exits with kExitFrameBudget); 0: no limit.
    double frameBudgetSeconds = 0.0;
    // What happens then (default: the message on stderr, exit); gets the message, should not return.
    std::function<void(const std::string&)> onFrameBudget;
};

// Frame i runs at time i·dt with deltaTime dt; with a frame budget each frame is waited for. Returns the executor after the last frame, or
// nullptr with diagnostics when creation or a frame failed.
std::unique_ptr<GlExecutor> runHeadless(const Workspace& ws, const RunSettings& settings, Diagnostics& diagnostics,
                                        const ExecutorOptions& options = {});

}  // namespace rmfx
