#pragma once
// Front end for the rmfx workspace format v1 (docs/workspace-format.md): XML → Workspace.
// Checks the file's own structure (elements, attributes, values); cross-references and
// shaders are checked by validateWorkspace.

#include <filesystem>
#include <optional>
#include <string>

#include "core/Diagnostic.h"
#include "model/Workspace.h"

namespace rmfx {

struct ParsedWorkspace {
    std::optional<Workspace> workspace;  // present when there are no errors
    Diagnostics diagnostics;
};

ParsedWorkspace parseWorkspaceFile(const std::filesystem::path& path);
// `path` names the text in diagnostics; `folder` is where relative file references resolve.
ParsedWorkspace parseWorkspaceText(const std::string& text, const std::filesystem::path& path,
                                   const std::filesystem::path& folder);

}  // namespace rmfx
