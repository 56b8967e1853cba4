#pragma once
// Warnings for run arguments that would change nothing, said before the run so that a user who
// gave an image does not take the unchanged output for the image's effect:
// - a --texture whose texture no pass that runs samples (its passes disabled, culled by the
//   effects asked for or by an --input), or that its passes read only while a variable has
//   another value (<texture read-when="VARIABLE=VALUE">): the warning names the setting;
// - an --input whose image no pass that runs samples.
// Pure: the pass graphs of the frame plan, no GL.

#include <vector>

#include "core/Diagnostic.h"
#include "graph/FramePlan.h"
#include "model/Workspace.h"
#include "validation/ImageInputs.h"
#include "validation/TextureArguments.h"

namespace rmfx {

// `ws` with its overrides applied; `options` as the run will plan its frame (effects asked
// for, the inputs given). Warnings name the argument as the user wrote it.
Diagnostics unreadArgumentWarnings(const Workspace& ws, const FramePlanOptions& options,
                                   const std::vector<TextureArgument>& textures, const std::vector<InputArgument>& inputs);

}  // namespace rmfx
