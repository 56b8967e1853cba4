#include "core/ShortNumber.h"

#include <cstdio>

namespace rmfx {

std::string shortNumber(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", value);
    return text;
}

}  // namespace rmfx
