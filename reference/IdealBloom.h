#pragma once
// The bloom stage's ideal (effects/variants/bloom.xml), what `rmfx bench` measures the bloom
// variants against: result* = S + Bloom_Strength · G * B, with S the sanitised input
// (sanitisedInput, StageInput.h), B = max(S − Bloom_Threshold, 0) per channel and G the Gaussian
// of sigma = Bloom_Sigma · H pixels at full resolution, black outside the image. Float64 on rgb;
// alpha is not used.

#include <vector>

#include "reference/CpuImage.h"

namespace rmfx::test {

struct BloomParameters {
    double threshold = 1.0;
    double strength = 0.5;
    double sigma = 0.03125;  // fraction of the image height
};

// Weights of the sampled Gaussian at offsets −R..R, R = ceil(4 sigma), normalised to sum 1 over
// those taps. sigma ≤ 0: the single tap 1.
std::vector<double> gaussianKernel(double sigmaPixels);

// Separable convolution with `kernel` (odd length, centred, symmetric) along x then y; outside is
// black.
RefImage separableBlur(const RefImage& image, const std::vector<double>& kernel);

// max(S − threshold, 0) per rgb channel.
RefImage brightPass(const RefImage& sanitised, double threshold);

RefImage idealBloom(const RefImage& sanitised, const BloomParameters& p);

}  // namespace rmfx::test
