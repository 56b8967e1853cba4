#include "bench/accuracy/IdealLuminance.h"

#include <algorithm>
#include <cmath>

namespace rmfx::accuracy {

SceneLuminance idealLuminance(const LinearImage& sanitised, double delta) {
    SceneLuminance out;
    if (sanitised.pixelCount() == 0) return out;
    // Per-row sums keep the float64 rounding of the total far below any variant's error.
    double total = 0.0;
    for (int y = 0; y < sanitised.height; ++y) {
        double row = 0.0;
        for (int x = 0; x < sanitised.width; ++x) {
            double Y = luminanceAt(sanitised, x, y);
            row += std::log(delta + Y);
            out.largest = std::max(out.largest, Y);
        }
        total += row;
    }
    out.logAverage = std::exp(total / static_cast<double>(sanitised.pixelCount()));
    return out;
}

}  // namespace rmfx::accuracy
