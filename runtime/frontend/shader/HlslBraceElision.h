#pragma once
// fxc accepts an array of vectors or matrices initialised by a flat list of scalars, C's brace
// elision (`float2 samples[12] = { -0.33, -0.41, -0.84, … };`, 24 numbers); glslang's HLSL front
// end rejects it ("cannot convert parameter 13 from const float to 2-component vector"). This
// step gives such a list the braces fxc implied, one pair per element, before glslang reads it.

#include <string>

namespace rmfx {

// `code` with every `TYPE NAME[N] = { … }` whose TYPE is a vector or matrix (float2 … float4x4,
// half, int, uint, bool, double), N a number and the list N × (components of TYPE) expressions
// without braces of their own, rewritten as `{ {…}, {…}, … }`. Only braces are inserted, so lines
// and columns before each insertion keep their place; anything else is returned unchanged.
std::string nestFlatArrayInitializers(const std::string& code);

}  // namespace rmfx
