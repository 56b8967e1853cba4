#include "run/HeadlessRun.h"

#include <optional>

#include <epoxy/gl.h>

#include "core/FrameWatchdog.h"

namespace rmfx {

std::unique_ptr<GlExecutor> runHeadless(const Workspace& ws, const RunSettings& settings, Diagnostics& diagnostics,
                                        const ExecutorOptions& options) {
    glm::ivec2 size = settings.size.x > 0 ? settings.size : glm::ivec2(ws.width, ws.height);
    auto executor = GlExecutor::create(ws, size, diagnostics, options);
    if (!executor) return nullptr;
    std::optional<FrameWatchdog> watchdog;
    if (settings.frameBudgetSeconds > 0) watchdog.emplace(settings.frameBudgetSeconds, settings.onFrameBudget);
    for (int i = 0; i < settings.frames; ++i) {
        if (watchdog) watchdog->arm("frame " + std::to_string(i + 1) + " of " + ws.path.string());
        Diagnostics frame = executor->renderFrame({static_cast<float>(i) * settings.deltaTime, settings.deltaTime});
        if (watchdog) {
            glFinish();
            watchdog->disarm();
        }
        diagnostics.insert(diagnostics.end(), frame.begin(), frame.end());
        if (hasErrors(frame)) return nullptr;
    }
    return executor;
}

}  // namespace rmfx
