#include "editor/EffectSession.h"

#include "runtime/WorkspaceLoader.h"

namespace rmfx::editor {

std::unique_ptr<EffectSession> EffectSession::open(const std::filesystem::path& file, glm::ivec2 viewport,
                                                   const std::vector<std::pair<std::string, std::string>>& overrides,
                                                   Diagnostics& diagnostics) {
    LoadedWorkspace loaded = loadWorkspace(file);
    diagnostics.insert(diagnostics.end(), loaded.diagnostics.begin(), loaded.diagnostics.end());
    if (!loaded.workspace) return nullptr;
    Diagnostics bad = applyOverrides(*loaded.workspace, overrides);
    diagnostics.insert(diagnostics.end(), bad.begin(), bad.end());
    if (hasErrors(bad)) return nullptr;
    auto session = std::unique_ptr<EffectSession>(new EffectSession);
    session->workspace_ = std::move(*loaded.workspace);
    if (viewport.x < 1) viewport = {session->workspace_.width, session->workspace_.height};
    session->executor_ = GlExecutor::create(session->workspace_, viewport, diagnostics);
    if (!session->executor_) return nullptr;
    return session;
}

bool EffectSession::poll() { return false; }

std::string EffectSession::setVariable(const std::string& name, const Value& value) {
    return executor_->setVariable(name, value);
}

void EffectSession::resetVariable(const std::string& name) {
    if (const Variable* v = workspace_.findVariable(name)) executor_->setVariable(name, v->value);
}

}  // namespace rmfx::editor
