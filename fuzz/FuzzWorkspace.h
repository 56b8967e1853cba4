#pragma once
// What the "workspace" fuzz target does with a parsed workspace, for every front end's target
// (the XML format's, the .rfx importer's): validation without compiling shaders, --set
// overrides of every variable's own value (which must read back unchanged), the files it
// depends on, effect selection, the pass graph, the target plan and its limits.

#include "frontend/workspace/WorkspaceParser.h"

namespace rmfx::fuzz {

void checkParsedWorkspace(const Result<Workspace>& parsed);

}  // namespace rmfx::fuzz
