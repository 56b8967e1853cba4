#pragma once
// The bloom stage's ideal (effects/variants/bloom.xml): result* = S + Bloom_Strength · G * B, with
// S the sanitised input, B = max(S − Bloom_Threshold, 0) per channel and G the Gaussian of
// sigma = Bloom_Sigma · H pixels at full resolution, black outside the image.

#include <vector>

#include "bench/accuracy/LinearImage.h"

namespace rmfx::accuracy {

struct BloomParameters {
    double threshold = 1.0;
    double strength = 0.5;
    double sigma = 0.03125;  // fraction of the image height
};

// Weights of the sampled Gaussian at offsets −R..R, R = ceil(4 sigma), normalised to sum 1 over
// those taps. sigma ≤ 0: the single tap 1.
std::vector<double> gaussianKernel(double sigmaPixels);

// Separable convolution with `kernel` (odd length, centred) along x then y; outside is black.
LinearImage separableBlur(const LinearImage& image, const std::vector<double>& kernel);

// max(S − threshold, 0) per channel.
LinearImage brightPass(const LinearImage& sanitised, double threshold);

LinearImage idealBloom(const LinearImage& sanitised, const BloomParameters& p);

}  // namespace rmfx::accuracy
