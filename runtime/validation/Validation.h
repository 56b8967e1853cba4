#pragma once
// Checks a parsed workspace before any GL call: names and references, shader compilation with
// glslang, and that every active uniform has a value of its type. Which files the workspace's
// references name (and whether they exist) is the loader's MediaResolver step, before this.

#include <map>

#include "core/Diagnostic.h"
#include "core/Result.h"
#include "frontend/shader/PassProgram.h"
#include "model/EffectSelection.h"
#include "model/Workspace.h"

namespace rmfx {

struct ValidationOptions {
    bool compileShaders = true;  // off: structure and references only
};

// The programs validation assembled (with every effect asked for) and glslang compiled without
// an error, by index into Workspace::passes: handed to the compile step (compile/CompiledFrame.h)
// so that a run reads, assembles and compiles each shader once.
struct CheckedPrograms {
    ShaderPrelude prelude;  // what they were assembled with
    std::map<int, PassProgramSource> programs;
};

// With `handOver`, fills it (also when validation finds errors, with the passes it could check).
Result<void> validateWorkspace(const Workspace& ws, const ValidationOptions& options = {}, CheckedPrograms* handOver = nullptr);

}  // namespace rmfx
