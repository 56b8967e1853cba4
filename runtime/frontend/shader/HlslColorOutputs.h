#pragma once
// Direct3D 9's colour outputs below shader model 3: a vs_1_1…vs_2_x vertex shader writes COLORn to
// the colour registers oD0/oD1, which hold 0…1, so what it writes is clamped before the pixel
// shader reads it interpolated (ATI's Anisotropic example writes an ambient term of -0.6 there).
// vs_3_0 outputs are plain registers, unclamped; TEXCOORDn never is.

#include <string>

namespace rmfx {

// For a vertex shader of `profile` vs_1_1…vs_2_x (any case), appends to the translated GLSL's main
// a clamp to [0, 1] of each COLORn output (hlslVaryingName); other profiles, stages' code and code
// without such an output or without `void main()` come back unchanged. Added on the last line, so
// line numbers stay where they were.
std::string clampColorOutputs(std::string glsl, const std::string& profile);

}  // namespace rmfx
