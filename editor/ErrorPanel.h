#pragma once
// The errors of the last failed reload and of the newest frame, in red, each as
// "file:line: error: element: message"; the window keeps showing the last good frame meanwhile.

#include "runtime/Diagnostic.h"

namespace rmfx::editor {

// Draws nothing when there is nothing to show.
void drawErrorPanel(const Diagnostics& reloadErrors, const Diagnostics& frameErrors);

}  // namespace rmfx::editor
