#pragma once
// Checks a parsed workspace before any GL call: names and references, shader compilation with
// glslang, and that every active uniform has a value of its type. Which files the workspace's
// references name (and whether they exist) is the loader's MediaResolver step, before this.

#include "core/Diagnostic.h"
#include "core/Result.h"
#include "model/Workspace.h"

namespace rmfx {

struct ValidationOptions {
    bool compileShaders = true;  // off: structure and references only
};

Result<void> validateWorkspace(const Workspace& ws, const ValidationOptions& options = {});

}  // namespace rmfx
