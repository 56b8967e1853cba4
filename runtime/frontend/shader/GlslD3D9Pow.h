#pragma once
// Direct3D 9's pow raises the absolute value of its base (the `pow` instruction: |x|^y), where
// GLSL's pow of a negative base is undefined (NaN on Mesa and most GPUs): a specular term
// `pow(dot(R, -V), 20)` left unclamped, as lazyartist's Lighting_Test3.rfx has it, is a tiny
// positive number in Direct3D and a black crescent in GLSL. And 0^0 is 1 in Direct3D 9, undefined
// in GLSL: a frame mask `pow(f, 0)` with f = 0 on the picture's edge (POST/rastr.rfx).

#include <string>

namespace rmfx {

// The GLSL translated from a Direct3D 9 HLSL shader with each pow(…) call made rm_d3d9_pow(…),
// defined for float and vec2…vec4 (the SPIR-V the GLSL comes from has operands of one type) as
// pow(abs(x), y), and 1 where y is 0, the definitions put after the #version line. Code without pow comes back as it is.
std::string powOfAbsoluteBase(std::string glsl);

}  // namespace rmfx
