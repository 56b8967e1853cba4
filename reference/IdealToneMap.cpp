#include "reference/IdealToneMap.h"

#include <algorithm>
#include <cmath>

#include "reference/StageInput.h"

namespace rmfx::test {

RefImage toneMapDisplay(const RefImage& sanitised, const ToneMapParameters& p) {
    RefImage out(sanitised.width, sanitised.height);
    const double white2 = p.whitePoint * p.whitePoint;
    const double scale = p.middleGray / std::max(p.sceneLuminance, 1e-6);
    for (int y = 0; y < out.height; ++y)
        for (int x = 0; x < out.width; ++x) {
            const glm::dvec4& t = sanitised.at(x, y);
            double r = t.r * p.exposure, g = t.g * p.exposure, b = t.b * p.exposure;
            double Y = rec709Luminance({r, g, b});
            if (!(Y > 0.0)) continue;
            double L = scale * Y;
            double Ld = L * (1.0 + L / white2) / (1.0 + L);
            double k = Ld / Y;
            out.at(x, y) = glm::dvec4(std::clamp(r * k, 0.0, 1.0), std::clamp(g * k, 0.0, 1.0),
                                      std::clamp(b * k, 0.0, 1.0), 0.0);
        }
    return out;
}

double srgbEncode(double linear) {
    return linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}

double srgbDecode(double encoded) {
    return encoded <= 0.04045 ? encoded / 12.92 : std::pow((encoded + 0.055) / 1.055, 2.4);
}

RefImage eightBitSrgb(const RefImage& display) {
    RefImage out = display;
    for (glm::dvec4& t : out.texels)
        for (int c = 0; c < 3; ++c) t[c] = std::floor(std::clamp(srgbEncode(t[c]), 0.0, 1.0) * 255.0 + 0.5);
    return out;
}

RefImage idealToneMap(const RefImage& sanitised, const ToneMapParameters& p) {
    return eightBitSrgb(toneMapDisplay(sanitised, p));
}

}  // namespace rmfx::test
