#pragma once
// Direct3D 9's pixel shader 1.x constants: a ps_1_1…ps_1_4 constant register holds [-1, 1], as
// the assembly path reads it (D3DAsmToHlsl), and so does an HLSL shader fxc compiled for those
// targets: Motion Blur's ps_1_4 `saturate(dot(lightDir, normal))` with lightDir (4.2, 1.4, -0.8)
// read (1, 1, -0.8).

#include <string>

namespace rmfx {

// For a pixel shader of `profile` ps_1_x (any case), each read of a float scalar or vector uniform
// of the translated GLSL becomes clamp(NAME, -1.0, 1.0); arrays, matrices, samplers, other
// profiles and code without such uniforms come back unchanged.
std::string clampPs1xConstants(std::string glsl, const std::string& profile);

}  // namespace rmfx
