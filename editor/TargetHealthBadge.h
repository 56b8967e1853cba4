#pragma once
// What the target browser shows of each target's numeric health (rmfx edit --check, the panel's
// "Check targets" box; model/TargetHealth.h): a badge under its thumbnail and, on hover, the first
// bad pixel. The badge tells what the thumbnail shows: the counts of the last pass of the frame
// that wrote the target, and where that pass counted only the pixels it drew over what the target
// held (PassHealth::ownPixelsOnly), those of the passes before it back to one that covered it.

#include <map>
#include <string>

#include "model/TargetHealth.h"

namespace rmfx::editor {

struct TargetHealthBadge {
    // "NaN 27 +Inf 9 neg 153": each kind found, errors first, with its pixel count; empty when
    // none was found (or the format cannot show any: see `inspected`).
    std::string text;
    bool error = false;      // NaN or an infinity (drawn red); else only warnings (amber)
    bool inspected = true;   // false: a normalised format, which clamps whatever is written
    // The tooltip: for each kind, the pass and count; where this target's pass was the frame's
    // first to write a kind, that finding in full (pixel, value, the inputs there).
    std::string details;
};

std::map<std::string, TargetHealthBadge> targetHealthBadges(const FrameHealth& health);

}  // namespace rmfx::editor
