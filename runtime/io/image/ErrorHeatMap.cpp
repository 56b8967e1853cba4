#include "io/image/ErrorHeatMap.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace rmfx {
namespace {

// Matplotlib's magma at nine evenly spaced points, 8-bit sRGB.
constexpr std::array<std::array<double, 3>, 9> kMagma{{{0, 0, 4},
                                                       {28, 16, 68},
                                                       {79, 18, 123},
                                                       {129, 37, 129},
                                                       {181, 54, 122},
                                                       {229, 80, 100},
                                                       {251, 135, 97},
                                                       {254, 194, 135},
                                                       {252, 253, 191}}};

}  // namespace

Image errorHeatMap(const Image& difference, double scale) {
    Image heat;
    heat.width = difference.width;
    heat.height = difference.height;
    heat.channels = 3;
    heat.highDynamicRange = false;
    heat.bitsPerChannel = 8;
    heat.pixels.assign(static_cast<size_t>(heat.width) * heat.height * 3, 0.0f);
    const size_t count = static_cast<size_t>(heat.width) * heat.height;
    for (size_t i = 0; i < count; ++i) {
        double e = 0;
        for (int k = 0; k < difference.channels; ++k) {
            double v = difference.pixels[i * difference.channels + k];
            e = std::max(e, std::isnan(v) ? HUGE_VAL : std::abs(v));
        }
        std::array<double, 3> colour{0, 229, 255};  // cyan: beyond the scale
        if (e <= scale) {
            double t = scale > 0 ? e / scale * 8.0 : 0.0;
            int k = std::min(7, static_cast<int>(t));
            double f = t - k;
            for (int c = 0; c < 3; ++c) colour[c] = kMagma[k][c] + f * (kMagma[k + 1][c] - kMagma[k][c]);
        }
        for (int c = 0; c < 3; ++c) heat.pixels[i * 3 + c] = static_cast<float>(std::round(colour[c]) / 255.0);
    }
    return heat;
}

}  // namespace rmfx
