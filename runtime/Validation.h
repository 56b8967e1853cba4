#pragma once
// Checks a parsed workspace before any GL call: names and references, files on disk, shader
// compilation with glslang, and that every active uniform has a value of its type.

#include "runtime/Diagnostic.h"
#include "runtime/Workspace.h"

namespace rmfx {

struct ValidationOptions {
    bool compileShaders = true;  // off: structure and references only
};

Diagnostics validateWorkspace(const Workspace& ws, const ValidationOptions& options = {});

}  // namespace rmfx
