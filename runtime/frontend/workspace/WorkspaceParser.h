#pragma once
// Front end for the rmfx workspace format v1 (docs/workspace-format.md): XML → Workspace.
// Checks the file's own structure (elements, attributes, values); cross-references and
// shaders are checked by validateWorkspace.

#include <filesystem>
#include <string>

#include "core/Result.h"
#include "model/Workspace.h"

namespace rmfx {

// The workspace with its warnings, or the diagnostics with at least one error.
Result<Workspace> parseWorkspaceFile(const std::filesystem::path& path);
// `path` names the text in diagnostics; `folder` is where relative file references resolve.
Result<Workspace> parseWorkspaceText(const std::string& text, const std::filesystem::path& path,
                                   const std::filesystem::path& folder);

}  // namespace rmfx
