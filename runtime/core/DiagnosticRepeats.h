#pragma once
// Validation and the GL build assemble the same shaders and warn about them the same way; what a
// command has shown once it does not show again.

#include "core/Diagnostic.h"

namespace rmfx {

// `later` without those `shown` already holds (the same severity, place, element and message).
Diagnostics withoutRepeats(Diagnostics later, const Diagnostics& shown);

}  // namespace rmfx
