#include "run/HeadlessRun.h"

#include <optional>

#include <epoxy/gl.h>

#include "core/FrameWatchdog.h"

namespace rmfx {

Result<std::unique_ptr<GlExecutor>> runHeadless(const Workspace& ws, const RunSettings& settings,
                                                const ExecutorOptions& options) {
    using Run = Result<std::unique_ptr<GlExecutor>>;
    glm::ivec2 size = settings.size.x > 0 ? settings.size : glm::ivec2(ws.width, ws.height);
    auto created = GlExecutor::create(std::make_shared<const Workspace>(ws), size, options);
    if (!created) return Run::failure(created.takeDiagnostics());
    Diagnostics diagnostics = created.takeDiagnostics();
    std::unique_ptr<GlExecutor> executor = std::move(*created);
    std::optional<FrameWatchdog> watchdog;
    if (settings.frameBudgetSeconds > 0) watchdog.emplace(settings.frameBudgetSeconds, settings.onFrameBudget);
    for (int i = 0; i < settings.frames; ++i) {
        if (watchdog) watchdog->arm("frame " + std::to_string(i + 1) + " of " + ws.path.string());
        Diagnostics frame = executor->renderFrame({static_cast<float>(i) * settings.deltaTime, settings.deltaTime}).takeDiagnostics();
        if (watchdog) {
            glFinish();
            watchdog->disarm();
        }
        diagnostics.insert(diagnostics.end(), frame.begin(), frame.end());
        if (hasErrors(frame)) return Run::failure(std::move(diagnostics));
    }
    return Run(std::move(executor), std::move(diagnostics));
}

}  // namespace rmfx
