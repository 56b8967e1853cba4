#pragma once
// Checks a parsed workspace before any GL call: names and references, shader compilation with
// glslang, and that every active uniform has a value of its type. Which files the workspace's
// references name (and whether they exist) is the loader's MediaResolver step, before this.

#include "core/Diagnostic.h"
#include "io/media/MediaResolver.h"
#include "model/Workspace.h"

namespace rmfx {

struct ValidationOptions {
    bool compileShaders = true;  // off: structure and references only
    MediaOptions media{};        // how loadWorkspace resolves file references (search path, sandbox)
};

Diagnostics validateWorkspace(const Workspace& ws, const ValidationOptions& options = {});

}  // namespace rmfx
