#pragma once
// Float64 references of the luminance stage (effects/variants/luminance.xml), from the definitions
// of issue 7's contract: the ideal log-average Lavg = exp(mean over all pixels of log(delta + Y)),
// Y the Rec.709 luminance of the sanitised Input, and models of what the cheaper variants compute
// (the sampled 64² chain of a downsampled image, the histogram with percentiles).

#include <vector>

#include <glm/vec3.hpp>

#include "reference/CpuImage.h"

namespace rmfx::test {

struct LogAverage {
    double lavg = 0.0;  // r of the luminance target
    double peak = 0.0;  // g: the largest Y
};

// exp(mean of log(delta + Y)) over every texel of `image`, sanitised, each weighing alike, and the
// largest Y. On Input it is the ideal, what the `exact` variant must give; on the image `sampled64`
// downsampled, what its 64² chain must give (its footprints partition that image and the chain
// weighs them by texel count).
LogAverage logAverage(const RefImage& image, double delta);

// `sampled64`'s first step: `input` sanitised and box-averaged exactly into ceil(size / factor)
// texels (edge blocks average the pixels they have), before the target format rounds them.
RefImage boxDownsampled(const RefImage& input, int factor);

struct HistogramSettings {
    int bins = 64;
    double minLog2 = -16.0, maxLog2 = 16.0;
    double low = 0.0, high = 1.0;
};

// The count of each bin of log2(Y); Y below the range (0 included) in the first bin, above it in
// the last.
std::vector<double> logHistogram(const RefImage& input, const HistogramSettings& settings);
int histogramBin(double y, const HistogramSettings& settings);
double histogramBinCentreLog2(int bin, const HistogramSettings& settings);

// `histogram`: the pixels sorted by bin, the ranks between low and high of the count (partial
// bins weighing the part inside), each at log(delta + 2^centre); exp of their mean. With low >=
// high, the bin at rank low. The peak is the largest Y of the input.
LogAverage histogramLogAverage(const RefImage& input, double delta, const HistogramSettings& settings);

}  // namespace rmfx::test
