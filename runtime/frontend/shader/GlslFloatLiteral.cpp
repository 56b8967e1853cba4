#include "frontend/shader/GlslFloatLiteral.h"

#include <cstdio>

namespace rmfx {

std::string glslFloatLiteral(double value) {
    char text[40];
    std::snprintf(text, sizeof text, "%.9g", value);
    std::string s = text;
    if (s.find_first_of(".eEn") == std::string::npos) s += ".0";
    return s;
}

}  // namespace rmfx
