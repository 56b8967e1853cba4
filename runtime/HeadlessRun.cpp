#include "runtime/HeadlessRun.h"

namespace rmfx {

std::unique_ptr<GlExecutor> runHeadless(const Workspace& ws, const RunSettings& settings, Diagnostics& diagnostics,
                                        const ExecutorOptions& options) {
    glm::ivec2 size = settings.size.x > 0 ? settings.size : glm::ivec2(ws.width, ws.height);
    auto executor = GlExecutor::create(ws, size, diagnostics, options);
    if (!executor) return nullptr;
    for (int i = 0; i < settings.frames; ++i) {
        Diagnostics frame = executor->renderFrame({static_cast<float>(i) * settings.deltaTime, settings.deltaTime});
        diagnostics.insert(diagnostics.end(), frame.begin(), frame.end());
        if (hasErrors(frame)) return nullptr;
    }
    return executor;
}

}  // namespace rmfx
