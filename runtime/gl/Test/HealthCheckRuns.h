#pragma once
// What the health-check GL tests share: a workspace run with --check by a given method.

#include <memory>

#include "gl/GlExecutor.h"
#include "tests/support/GlTestSupport.h"

namespace rmfx::test {

inline GlRun runChecked(std::unique_ptr<Workspace> ws, glm::ivec2 size, int frames = 1,
                        HealthCheckMethod method = HealthCheckMethod::AfterPass) {
    ExecutorOptions options;
    options.checkHealth = true;
    options.healthCheckMethod = method;
    return runWorkspace(std::move(ws), {size, frames, 1.0f / 60.0f}, options);
}

}  // namespace rmfx::test
