#pragma once
// A number for a person: at most six significant digits ("%.6g": 0.484375, 1e+06, nan, inf).

#include <string>

namespace rmfx {

std::string shortNumber(double value);

}  // namespace rmfx
