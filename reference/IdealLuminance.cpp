#include "reference/IdealLuminance.h"

#include <algorithm>
#include <cmath>

#include "reference/StageInput.h"

namespace rmfx::test {

SceneLuminance idealLuminance(const RefImage& sanitised, double delta) {
    SceneLuminance out;
    if (sanitised.width <= 0 || sanitised.height <= 0) return out;
    // Per-row sums keep the float64 rounding of the total far below any variant's error. The top
    // row first (rows are bottom-up): the order the bench has always summed in, bit for bit.
    double total = 0.0;
    for (int y = sanitised.height - 1; y >= 0; --y) {
        double row = 0.0;
        for (int x = 0; x < sanitised.width; ++x) {
            double Y = rec709Luminance(glm::dvec3(sanitised.at(x, y)));
            row += std::log(delta + Y);
            out.largest = std::max(out.largest, Y);
        }
        total += row;
    }
    out.logAverage = std::exp(total / static_cast<double>(sanitised.texels.size()));
    return out;
}

}  // namespace rmfx::test
