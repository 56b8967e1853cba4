#pragma once
// The luminance stage's ideal (effects/variants/luminance.xml): the exact log-average
// Lavg = exp(mean over every pixel of log(delta + Y(S))) and the largest Y, in float64.

#include "bench/accuracy/LinearImage.h"

namespace rmfx::accuracy {

struct SceneLuminance {
    double logAverage = 0.0;
    double largest = 0.0;
};

SceneLuminance idealLuminance(const LinearImage& sanitised, double delta = 1e-4);

}  // namespace rmfx::accuracy
