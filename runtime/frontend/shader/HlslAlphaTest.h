#pragma once
// Direct3D 9's alpha test after a translated pixel shader (model/Workspace.h AlphaTest): a
// discard appended to the GLSL's main, on its last line, so line numbers stay where they were.

#include <string>

#include "model/Workspace.h"

namespace rmfx {

// Discards the fragment unless colour output 0's alpha (rm_hlsl_out_COLOR0.a) passes
// `alpha FUNC ref`. False, with the code unchanged, when the code has no `void main()` or does not
// write rm_hlsl_out_COLOR0.
bool appendAlphaTest(std::string& glsl, const AlphaTest& test);

}  // namespace rmfx
