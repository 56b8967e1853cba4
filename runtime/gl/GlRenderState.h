#pragma once
// A pass's blend, depth and rasterizer state, set on the current GL context before it draws.

#include "model/Workspace.h"

namespace rmfx {

// `compatibility`: the context is a compatibility-profile one, which draws front and back faces
// in their own polygon modes and lines wider than a pixel (validation refuses both otherwise).
// `rowsTopFirst`: the workspace's passes draw the picture's top row at GL's row 0
// (rowsTopFirst(TextureSpace)), which turns the winding GL sees over.
void applyRenderState(const Pass& pass, bool compatibility, bool rowsTopFirst);
// After the pass's draw: filled polygons and 1-pixel lines again, where the pass changed them.
void restoreFilledPolygons(const Pass& pass, bool compatibility);

}  // namespace rmfx
