#pragma once
// Renders a workspace for a fixed number of frames with a fixed time step: what `rmfx render`,
// replay tests and the GL tests all do. Needs a current GL context.

#include <memory>

#include <glm/vec2.hpp>

#include "runtime/Diagnostic.h"
#include "runtime/GlExecutor.h"
#include "runtime/Workspace.h"

namespace rmfx {

struct RunSettings {
    glm::ivec2 size{0};          // 0: the workspace's size
    int frames = 1;
    float deltaTime = 1.0f / 60.0f;
};

// Frame i runs at time i·dt with deltaTime dt. Returns the executor after the last frame, or
// nullptr with diagnostics when creation or a frame failed.
std::unique_ptr<GlExecutor> runHeadless(const Workspace& ws, const RunSettings& settings, Diagnostics& diagnostics,
                                        const ExecutorOptions& options = {});

}  // namespace rmfx
