#include "reference/ToneMapVariantsReference.h"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>
#include <glm/exponential.hpp>

#include "reference/StageInput.h"

namespace rmfx::test {

double photographicRatio(double l, double whitePoint) {
    double white2 = std::max(whitePoint * whitePoint, 1e-12);
    return (1.0 + l / white2) / (1.0 + l);
}

double tableRatio(double l, double whitePoint, int entries) {
    double t = std::clamp((std::log2(l) + 12.0) / 24.0, 0.0, 1.0) * (entries - 1);
    int i = std::min(static_cast<int>(std::floor(t)), entries - 2);
    double f = t - i;
    auto entry = [&](int k) { return photographicRatio(std::exp2(-12.0 + 24.0 * k / (entries - 1)), whitePoint); };
    return entry(i) * (1.0 - f) + entry(i + 1) * f;
}

double srgbOetf(double c) { return c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055; }

glm::dvec3 toneMapped(glm::dvec3 hdr, const ToneMapSettings& s, ToneMapCurve curve) {
    double y = rec709Luminance(hdr);
    if (!(y > 0.0)) return glm::dvec3(0.0);
    double scale = s.middleGray / std::max(s.sceneLuminance, 1e-6);
    double l = y * scale;
    double ratio = curve == ToneMapCurve::Lut256  ? tableRatio(l, s.whitePoint, 256)
                   : curve == ToneMapCurve::Lut32 ? tableRatio(l, s.whitePoint, 32)
                                                  : photographicRatio(l, s.whitePoint);
    glm::dvec3 display = glm::clamp(hdr * (scale * ratio), 0.0, 1.0);
    if (curve == ToneMapCurve::FastGamma) return glm::sqrt(display);
    return {srgbOetf(display.r), srgbOetf(display.g), srgbOetf(display.b)};
}

}  // namespace rmfx::test
