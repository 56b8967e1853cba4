#pragma once
// A pass's blend, depth and rasterizer state, set on the current GL context before it draws.

#include "model/Workspace.h"

namespace rmfx {

void applyRenderState(const Pass& pass);

}  // namespace rmfx
