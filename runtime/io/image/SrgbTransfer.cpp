#include <cmath>

#include "io/image/ImageIO.h"

namespace rmfx {

float srgbEncode(float linear) {
    const double v = linear;
    return static_cast<float>(v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055);
}

float srgbDecode(float encoded) {
    const double v = encoded;
    return static_cast<float>(v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4));
}

}  // namespace rmfx
