#pragma once
// The running effect the editor shows: the workspace, its executor and the variable values set in
// the panel. The one place the editor creates and polls an executor.

#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <glm/vec2.hpp>

#include "runtime/Diagnostic.h"
#include "runtime/GlExecutor.h"
#include "runtime/Workspace.h"

namespace rmfx::editor {

class EffectSession {
public:
    // nullptr with diagnostics when the workspace does not load or build.
    static std::unique_ptr<EffectSession> open(const std::filesystem::path& file, glm::ivec2 viewport,
                                               const std::vector<std::pair<std::string, std::string>>& overrides,
                                               Diagnostics& diagnostics);
    bool poll();  // true when something was rebuilt or failed
    GlExecutor& executor() { return *executor_; }
    const Workspace& workspace() const { return workspace_; }
    const Diagnostics& errors() const { return errors_; }
    std::string setVariable(const std::string& name, const Value& value);
    void resetVariable(const std::string& name);
    double lastReloadMilliseconds() const { return 0.0; }

private:
    Workspace workspace_;
    std::unique_ptr<GlExecutor> executor_;
    Diagnostics errors_;
};

}  // namespace rmfx::editor
