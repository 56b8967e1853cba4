#pragma once
// The names the HLSL translated from assembly (D3DAsmToHlsl) may give its globals: an RmShaderConstant's
// variable and a sampler stage's texture object are declared under their own names, so that rmfx
// binds them by name, and not every name can be one.

#include <string>

namespace rmfx::d3dasm {

// Whether `name` can be such a global: an identifier, not a word glslang's HLSL front end refuses
// or misreads (half, texture, in…), not one of the translation's own names (r3, oT1, c, rm_…).
bool hlslIdentifier(const std::string& name);

}  // namespace rmfx::d3dasm
