#pragma once
// RenderMonkey packs colours (CLEAR_COLOR_VALUE, border and blend colours in states) into one
// signed 32-bit integer, ARGB from the top byte down, as Direct3D's D3DCOLOR does: -16777216 is
// opaque black (0xFF000000), 16711680 is red with alpha 0.

#include <glm/vec4.hpp>

namespace rmfx::rfx {

// The packed value as rgba in [0, 1]; `packed` is read modulo 2^32.
glm::vec4 unpackArgb(long long packed);

}  // namespace rmfx::rfx
