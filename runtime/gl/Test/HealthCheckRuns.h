#pragma once
// What the health-check GL tests share: the two methods, and a workspace run with --check by one.

#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "gl/GlExecutor.h"
#include "tests/support/GlTestSupport.h"

namespace rmfx::test {

// The two methods a parameterised test runs under, and the name each gives the test.
inline auto bothMethods() { return ::testing::Values(HealthCheckMethod::AfterPass, HealthCheckMethod::WhileDrawing); }
inline std::string methodName(const ::testing::TestParamInfo<HealthCheckMethod>& info) {
    return info.param == HealthCheckMethod::AfterPass ? "AfterPass" : "WhileDrawing";
}

inline GlRun runChecked(std::unique_ptr<Workspace> ws, glm::ivec2 size, int frames = 1,
                        HealthCheckMethod method = HealthCheckMethod::AfterPass) {
    ExecutorOptions options;
    options.checkHealth = true;
    options.healthCheckMethod = method;
    return runWorkspace(std::move(ws), {size, frames, 1.0f / 60.0f}, options);
}

}  // namespace rmfx::test
