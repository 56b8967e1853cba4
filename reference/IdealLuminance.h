#pragma once
// The luminance stage's ideal (effects/variants/luminance.xml), what `rmfx bench` measures the
// luminance variants against: the exact log-average Lavg = exp(mean over every pixel of
// log(delta + Y(S))) and the largest Y (Rec.709), in float64.

#include "reference/CpuImage.h"

namespace rmfx::test {

struct SceneLuminance {
    double logAverage = 0.0;
    double largest = 0.0;
};

SceneLuminance idealLuminance(const RefImage& sanitised, double delta = 1e-4);

}  // namespace rmfx::test
