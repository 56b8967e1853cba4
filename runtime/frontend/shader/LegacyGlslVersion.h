#pragma once
// Desktop GLSL written without #version for lenient drivers: GLSL 1.10 has no implicit int → float
// conversion, so `const float SCALE = 5 * PI;` or `float x = 1;` fail there, though the drivers
// RenderMonkey ran on (NVIDIA's among them) compiled them. Such a shader compiles with GLSL 1.20's
// rules, which allow them, when 1.10 rejects it and 1.20 does not. Never for GLSL ES.

#include <optional>
#include <string>

#include "model/Workspace.h"

namespace rmfx {

// When GLSL 1.10 rejects `code` (a complete stage without #version) and GLSL 1.20 accepts it:
// 1.10's first error, for the warning that says why 1.20 was used. nullopt otherwise, also when
// both reject it (the 1.10 errors are then the ones to show).
std::optional<std::string> rejectedOnlyByGlsl110(const std::string& code, ShaderStage stage);

}  // namespace rmfx
