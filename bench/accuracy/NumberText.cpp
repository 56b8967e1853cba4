#include "bench/accuracy/NumberText.h"

#include <cmath>
#include <cstdio>

namespace rmfx::accuracy {
namespace {

std::string nonFinite(double value) { return std::isnan(value) ? "nan" : value > 0 ? "inf" : "-inf"; }

}  // namespace

std::string numberText(double value, int significant) {
    if (!std::isfinite(value)) return nonFinite(value);
    char text[64];
    std::snprintf(text, sizeof text, "%.*g", significant, value);
    return text;
}

std::string fixedText(double value, int decimals) {
    if (!std::isfinite(value)) return nonFinite(value);
    char text[64];
    std::snprintf(text, sizeof text, "%.*f", decimals, value);
    return text;
}

}  // namespace rmfx::accuracy
