#pragma once
// `rmfx edit`: a window showing the running effect at its own size, 1:1, at the window's top-left
// corner, and beside it (to the right) the ImGui panel: errors, variables, camera, render targets,
// timing. docs/editor.md describes it.

#include "apps/EditorOptions.h"

namespace rmfx::editor {

using apps::EditorOptions;

inline constexpr int panelWidth = 460;        // screen units right of the effect
inline constexpr int minimumWindowHeight = 720;

// Runs until the window closes (or, with options.frames, for that many frames). Returns the exit
// status: 0, 1 for an invalid workspace or arguments, 2 for a window, GL or rendering failure.
int runEditor(const EditorOptions& options);

}  // namespace rmfx::editor
