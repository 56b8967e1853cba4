#pragma once
// The errors of the last failed reload and of the newest frame, in a red box, each as
// "file:line: error: element: message" (the window keeps showing the last good build meanwhile);
// then the warnings of the last reload (a tweaked value dropped, say) in yellow.

#include "core/Diagnostic.h"

namespace rmfx::editor {

// Draws nothing when there is nothing to show.
void drawErrorPanel(const Diagnostics& reloadErrors, const Diagnostics& frameErrors, const Diagnostics& reloadWarnings);

}  // namespace rmfx::editor
