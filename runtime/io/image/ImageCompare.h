#pragma once
// Compares a rendered image with a reference image through OpenImageIO and checks the error
// against limits: the per-channel error (absolute, or relative to the reference) or the
// per-pixel colour difference ΔE_ITP, its maximum, mean and a percentile, and the fraction of
// pixels whose error exceeds a threshold (docs/replay.md).

#include <optional>
#include <string>
#include <vector>

#include "io/image/ColorDifferenceItp.h"
#include "model/Image.h"

namespace rmfx {

enum class ErrorMetric {
    Absolute,  // |a − b|
    Relative,  // |a − b| / max(|b|, floor), b the reference
    Itp,       // ΔE_ITP of each pixel's colour (ColorDifferenceItp.h); alpha is not compared
};

// The p-th percentile of the errors (core/Percentile.h) may be at most `max`.
struct PercentileLimit {
    double percentile = 100;  // in (0, 100]
    double max = 0;
};

struct CompareLimits {
    ErrorMetric metric = ErrorMetric::Absolute;
    double floor = 1e-3;          // relative: the smallest denominator
    double luminance = kItpDefaultLuminance;  // itp: cd/m² of a value of 1.0
    // Errors: one for each channel of each pixel; with Itp, one for each pixel.
    std::optional<double> max;    // largest allowed error
    std::optional<double> mean;   // largest allowed mean error
    std::optional<PercentileLimit> percentile;
    std::optional<double> pixel;  // a pixel fails when one of its errors exceeds this
    double failFraction = 0;      // with `pixel`: the largest allowed fraction of failing pixels
};

struct CompareMetrics {
    double maxError = 0;
    int maxX = 0, maxY = 0, maxChannel = 0;  // where the largest error is (row 0 at the top)
    double meanError = 0;
    double percentileError = 0;   // at CompareLimits::percentile (0 without one)
    long long failingPixels = 0;  // pixels with an error above CompareLimits::pixel (0 without one)
    long long pixelCount = 0;
    double failFraction() const {
        return pixelCount > 0 ? static_cast<double>(failingPixels) / static_cast<double>(pixelCount) : 0.0;
    }
};

// One limit of CompareLimits against the value measured.
struct LimitCheck {
    enum class Kind { Max, Mean, Percentile, FailFraction };
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
    // One for each limit given, in the order max, mean, percentile, fail fraction.
    std::vector<LimitCheck> checks;
    // The error image, the images' size, one channel a channel of the images (ΔE_ITP: one
    // channel); empty when the sizes or channels differ. Errors where both images hold the same
    // NaN or infinity are 0 (with Itp: a pixel with a NaN or infinity in its colour).
    Image difference;
    ErrorMetric metric = ErrorMetric::Absolute;
    std::optional<double> percentile;  // of CompareLimits::percentile
    std::optional<double> pixelThreshold;

    bool passed() const;
    // What a check measures, for a person: "max relative error", "mean error", "99th percentile
    // ΔE_ITP", "fail fraction (pixels with error > 0.01)".
    std::string checkName(const LimitCheck& check) const;
    // What was measured against what was allowed, one clause a check, for a person:
    // "max error 0.03125 > 0.02 at x=17 y=40 channel 0; mean error 0.0004 ≤ 0.002".
    std::string describe() const;
};

// `actual` is the render, `reference` the stored image; a NaN or infinity matches the same
// value in the other image.
ImageComparison compareImages(const Image& actual, const Image& reference, const CompareLimits& limits);

}  // namespace rmfx
