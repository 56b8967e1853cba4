#pragma once
// Direct3D semantics (POSITION, TEXCOORD1, SV_Target…) and the GLSL names the HLSL translator
// gives the variables that carry them.

#include <optional>
#include <string>
#include <utility>

#include "model/Workspace.h"

namespace rmfx {

// "TEXCOORD3" → {"TEXCOORD", 3}; "COLOR" → {"COLOR", 0}; "SV_Position" → {"SV_POSITION", 0}.
std::pair<std::string, int> splitSemantic(const std::string& semantic);
// POSITION, POSITION0, SV_Position: what a vertex shader writes to gl_Position.
bool isPositionSemantic(const std::string& semantic);

// What Direct3D 9's rasterizer hands a pixel shader, which no vertex shader writes: VPOS, the
// pixel's position in whole numbers ((0, 0) the top-left pixel in a Direct3D texture space:
// gl_FragCoord.xy − 0.5, since those spaces draw the top row at GL's row 0), and VFACE, positive
// on front faces and negative on back faces. The GLSL expression of the value for an input of
// GLSL type `type` (float or vecN; VPOS's further components 0); nullopt for other semantics.
std::optional<std::string> pixelSystemValue(const std::string& semantic, const std::string& type);

// "TEXCOORD" → rm_hlsl_TEXCOORD0, "color1" → rm_hlsl_COLOR1: the GLSL name of a varying.
std::string hlslVaryingName(const std::string& semantic);
// The GLSL attribute name of a vertex input with that usage: (TexCoord, 1) → rm_hlsl_in_TEXCOORD1.
std::string hlslVertexInputName(VertexUsage usage, int usageIndex);

}  // namespace rmfx
