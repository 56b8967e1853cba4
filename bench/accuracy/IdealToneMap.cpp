#include "bench/accuracy/IdealToneMap.h"

#include <algorithm>
#include <cmath>

namespace rmfx::accuracy {

LinearImage toneMapDisplay(const LinearImage& sanitised, const ToneMapParameters& p) {
    LinearImage out(sanitised.width, sanitised.height);
    const double white2 = p.whitePoint * p.whitePoint;
    const double scale = p.middleGray / std::max(p.sceneLuminance, 1e-6);
    for (int y = 0; y < out.height; ++y)
        for (int x = 0; x < out.width; ++x) {
            double r = sanitised.at(x, y, 0) * p.exposure, g = sanitised.at(x, y, 1) * p.exposure,
                   b = sanitised.at(x, y, 2) * p.exposure;
            double Y = luminance(r, g, b);
            if (!(Y > 0.0)) continue;
            double L = scale * Y;
            double Ld = L * (1.0 + L / white2) / (1.0 + L);
            double k = Ld / Y;
            out.at(x, y, 0) = std::clamp(r * k, 0.0, 1.0);
            out.at(x, y, 1) = std::clamp(g * k, 0.0, 1.0);
            out.at(x, y, 2) = std::clamp(b * k, 0.0, 1.0);
        }
    return out;
}

double srgbEncode(double linear) {
    return linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}

double srgbDecode(double encoded) {
    return encoded <= 0.04045 ? encoded / 12.92 : std::pow((encoded + 0.055) / 1.055, 2.4);
}

LinearImage eightBitSrgb(const LinearImage& display) {
    LinearImage out = display;
    for (double& v : out.rgb) v = std::floor(std::clamp(srgbEncode(v), 0.0, 1.0) * 255.0 + 0.5);
    return out;
}

LinearImage idealToneMap(const LinearImage& sanitised, const ToneMapParameters& p) {
    return eightBitSrgb(toneMapDisplay(sanitised, p));
}

}  // namespace rmfx::accuracy
