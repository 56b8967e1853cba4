#pragma once
// Renders a workspace for a fixed number of frames with a fixed time step: what `rmfx render`,
// replay tests and the GL tests all do. Needs a current GL context.

#include <functional>
#include <memory>
#include <string>

#include <glm/vec2.hpp>

#include "core/Diagnostic.h"
#include "compile/RunPreparation.h"
#include "core/Result.h"
#include "gl/GlExecutor.h"
#include "model/RunSettings.h"
#include "model/Workspace.h"

namespace rmfx {

// Frame i runs at time i·dt with deltaTime dt; with a frame budget each frame is waited for. Returns the
// executor after the last frame (with the warnings of creation and every frame), or the diagnostics
// of the creation or frame that failed. The executor runs its own copy of `ws`.
Result<std::unique_ptr<GlExecutor>> runHeadless(const Workspace& ws, const RunSettings& settings,
                                                const ExecutorOptions& options = {});
// The same for a prepared run (compile/RunPreparation.h), at its viewport (settings.size is not read).
Result<std::unique_ptr<GlExecutor>> runHeadless(const PreparedRun& run, const RunSettings& settings, const GlRunSettings& gl = {});

}  // namespace rmfx
