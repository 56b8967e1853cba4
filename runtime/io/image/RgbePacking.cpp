#include "io/image/RgbePacking.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace rmfx {

namespace {
// The largest value the packing holds: mantissa 255 with exponent byte 255.
const double kLargest = std::ldexp(255.0 / 256.0, 127);
}  // namespace

Image packRgbe(const Image& image) {
    Image packed;
    packed.width = image.width;
    packed.height = image.height * 2;
    packed.channels = 3;
    packed.highDynamicRange = false;
    packed.bitsPerChannel = 8;
    packed.pixels.assign(static_cast<size_t>(packed.width) * packed.height * 3, 0.0f);
    const size_t half = static_cast<size_t>(image.width) * image.height;
    for (size_t i = 0; i < half; ++i) {
        std::array<double, 3> rgb{};
        for (int k = 0; k < 3; ++k) {
            double v = image.channels >= 3 ? image.pixels[i * image.channels + k] : image.pixels[i * image.channels];
            rgb[k] = std::isfinite(v) && v > 0 ? std::min(v, kLargest) : 0.0;
        }
        double largest = std::max({rgb[0], rgb[1], rgb[2]});
        if (largest < 1e-32) continue;
        int exponent = 0;
        double mantissa = std::frexp(largest, &exponent);  // largest = mantissa · 2^exponent, mantissa in [0.5, 1)
        double scale = mantissa * 256.0 / largest;
        for (int k = 0; k < 3; ++k)
            packed.pixels[i * 3 + k] = static_cast<float>(std::min(255.0, std::floor(rgb[k] * scale)) / 255.0);
        float e = static_cast<float>((exponent + 128) / 255.0);
        for (int k = 0; k < 3; ++k) packed.pixels[(half + i) * 3 + k] = e;
    }
    return packed;
}

double unpackRgbe(int mantissa, int exponent) {
    return exponent == 0 || mantissa == 0 ? 0.0 : (mantissa + 0.5) * std::ldexp(1.0, exponent - 136);
}

}  // namespace rmfx
