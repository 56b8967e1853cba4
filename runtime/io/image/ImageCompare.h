#pragma once
// Compares a rendered image with a reference image through OpenImageIO and checks the error
// against limits: the per-channel error (absolute, or relative to the reference), its maximum
// and mean, and the fraction of pixels whose error exceeds a threshold (docs/replay.md).

#include <optional>
#include <string>
#include <vector>

#include "model/Image.h"

namespace rmfx {

enum class ErrorMetric {
    Absolute,  // |a − b|
    Relative,  // |a − b| / max(|b|, floor), b the reference
};

struct CompareLimits {
    ErrorMetric metric = ErrorMetric::Absolute;
    double floor = 1e-3;          // relative: the smallest denominator
    std::optional<double> max;    // largest allowed error of any channel of any pixel
    std::optional<double> mean;   // largest allowed mean error over every channel of every pixel
    std::optional<double> pixel;  // a pixel fails when one of its channels' error exceeds this
    double failFraction = 0;      // with `pixel`: the largest allowed fraction of failing pixels
};

struct CompareMetrics {
    double maxError = 0;
    int maxX = 0, maxY = 0, maxChannel = 0;  // where the largest error is (row 0 at the top)
    double meanError = 0;
    long long failingPixels = 0;  // pixels with an error above CompareLimits::pixel (0 without one)
    long long pixelCount = 0;
    double failFraction() const {
        return pixelCount > 0 ? static_cast<double>(failingPixels) / static_cast<double>(pixelCount) : 0.0;
    }
};

// One limit of CompareLimits against the value measured.
struct LimitCheck {
    enum class Kind { Max, Mean, FailFraction };
    Kind kind;
    double value = 0;
    double limit = 0;
    bool passed() const { return value <= limit; }
};

struct ImageComparison {
    // Set when the images differ in a way no limit allows: size, channel count, or a NaN or
    // infinity in one image where the other has a different value. Empty otherwise.
    std::string problem;
    CompareMetrics metrics;        // over the finite values; zero when the sizes or channels differ
    std::vector<LimitCheck> checks;  // one for each limit given, in the order max, mean, fail fraction
    // The per-channel error image, the images' size; empty when the sizes or channels differ.
    // Values where both images hold the same NaN or infinity are 0.
    Image difference;
    ErrorMetric metric = ErrorMetric::Absolute;
    std::optional<double> pixelThreshold;

    bool passed() const;
    // What was measured against what was allowed, one clause a check, for a person:
    // "max error 0.03125 > 0.02 at x=17 y=40 channel 0; mean error 0.0004 ≤ 0.002".
    std::string describe() const;
};

// `actual` is the render, `reference` the stored image; a NaN or infinity matches the same
// value in the other image.
ImageComparison compareImages(const Image& actual, const Image& reference, const CompareLimits& limits);

}  // namespace rmfx
