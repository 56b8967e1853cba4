#include "run/HeadlessRun.h"

#include "run/FrameStepper.h"

namespace rmfx {

namespace {

using Run = Result<std::unique_ptr<GlExecutor>>;

Run runFrames(Run created, const Workspace& ws, const RunSettings& settings) {
    if (!created) return Run::failure(created.takeDiagnostics());
    Diagnostics diagnostics = created.takeDiagnostics();
    std::unique_ptr<GlExecutor> executor = std::move(*created);
    FrameStepper frames(settings.deltaTime, settings.frameBudgetSeconds, settings.onFrameBudget);
    for (int i = 0; i < settings.frames; ++i) {
        Diagnostics frame = frames.step(*executor, i, "frame " + std::to_string(i + 1) + " of " + ws.path.string()).takeDiagnostics();
        diagnostics.insert(diagnostics.end(), frame.begin(), frame.end());
        if (hasErrors(frame)) return Run::failure(std::move(diagnostics));
    }
    return Run(std::move(executor), std::move(diagnostics));
}

}  // namespace

Result<std::unique_ptr<GlExecutor>> runHeadless(const Workspace& ws, const RunSettings& settings,
                                                const ExecutorOptions& options) {
    glm::ivec2 size = settings.size.x > 0 ? settings.size : glm::ivec2(ws.width, ws.height);
    return runFrames(GlExecutor::create(std::make_shared<const Workspace>(ws), size, options), ws, settings);
}

Result<std::unique_ptr<GlExecutor>> runHeadless(const PreparedRun& run, const RunSettings& settings, const GlRunSettings& gl) {
    return runFrames(GlExecutor::create(run.frame, gl), run.ws(), settings);
}

}  // namespace rmfx
