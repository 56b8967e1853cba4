#pragma once
// Direct3D 9's fixed-function pixel fog after a translated ps_1_x / ps_2_x pixel shader
// (model/Workspace.h FixedFunctionFog): the blend is appended to the GLSL's main, on its last
// line, so line numbers stay where they were.

#include <string>

#include "model/Workspace.h"

namespace rmfx {

// Blends colour output 0 (rm_hlsl_out_COLOR0) toward the fog colour by the fragment's eye-space
// depth, 1 / gl_FragCoord.w (Direct3D's w-based fog). False, with the code unchanged, when the code
// has no `void main()` or does not write rm_hlsl_out_COLOR0.
bool appendFixedFunctionFog(std::string& glsl, const FixedFunctionFog& fog);

}  // namespace rmfx
