#pragma once
// Direct3D semantics (POSITION, TEXCOORD1, SV_Target…) and the GLSL names the HLSL translator
// gives the variables that carry them.

#include <string>
#include <utility>

#include "model/Workspace.h"

namespace rmfx {

// "TEXCOORD3" → {"TEXCOORD", 3}; "COLOR" → {"COLOR", 0}; "SV_Position" → {"SV_POSITION", 0}.
std::pair<std::string, int> splitSemantic(const std::string& semantic);
// POSITION, POSITION0, SV_Position: what a vertex shader writes to gl_Position.
bool isPositionSemantic(const std::string& semantic);

// "TEXCOORD" → rm_hlsl_TEXCOORD0, "color1" → rm_hlsl_COLOR1: the GLSL name of a varying.
std::string hlslVaryingName(const std::string& semantic);
// The GLSL attribute name of a vertex input with that usage: (TexCoord, 1) → rm_hlsl_in_TEXCOORD1.
std::string hlslVertexInputName(VertexUsage usage, int usageIndex);

}  // namespace rmfx
