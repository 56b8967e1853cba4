#pragma once
// A float as GLSL source text for the code rmfx writes into shaders (initial values, fog and
// alpha-test constants): nine significant digits, the float's exact value, always with a point or
// an exponent so that GLSL reads a float, not an int.

#include <string>

namespace rmfx {

std::string glslFloatLiteral(double value);

}  // namespace rmfx
