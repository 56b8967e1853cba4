#include "bench/accuracy/AccuracyMetrics.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

#include "bench/accuracy/IdealLuminance.h"
#include "bench/accuracy/IdealToneMap.h"

namespace rmfx::accuracy {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

double relative(double actual, double ideal, double floor) {
    double e = std::abs(actual - ideal) / std::max(ideal, floor);
    return std::isfinite(e) ? e : kInfinity;
}

}  // namespace

RelativeError relativeLuminanceError(const LinearImage& actual, const LinearImage& ideal, std::optional<double> floor) {
    assert(actual.width == ideal.width && actual.height == ideal.height);
    RelativeError out;
    const size_t n = ideal.pixelCount();
    if (n == 0) return out;
    if (!floor) {
        double sum = 0.0;
        for (int y = 0; y < ideal.height; ++y)
            for (int x = 0; x < ideal.width; ++x) sum += luminanceAt(ideal, x, y);
        double f = 1e-3 * sum / static_cast<double>(n);
        floor = f > 0.0 ? f : 1e-30;
    }
    double total = 0.0;
    for (int y = 0; y < ideal.height; ++y)
        for (int x = 0; x < ideal.width; ++x) {
            double e = relative(luminanceAt(actual, x, y), luminanceAt(ideal, x, y), *floor);
            out.max = std::max(out.max, e);
            total += e;
        }
    out.mean = total / static_cast<double>(n);
    return out;
}

double psnr8(const LinearImage& a, const LinearImage& b) {
    assert(a.rgb.size() == b.rgb.size());
    if (a.rgb.empty()) return kInfinity;
    double sum = 0.0;
    for (size_t i = 0; i < a.rgb.size(); ++i) sum += (a.rgb[i] - b.rgb[i]) * (a.rgb[i] - b.rgb[i]);
    double mse = sum / static_cast<double>(a.rgb.size());
    if (std::isnan(mse)) return -kInfinity;
    return mse == 0.0 ? kInfinity : 10.0 * std::log10(255.0 * 255.0 / mse);
}

LinearImage referenceToneMap(const LinearImage& image, double logAverage) {
    ToneMapParameters p;
    p.sceneLuminance = logAverage;
    p.middleGray = 0.18;
    p.whitePoint = 4.0;
    p.exposure = 1.0;
    return idealToneMap(image, p);
}

ErrorMetrics imageStageMetrics(const LinearImage& actual, const LinearImage& ideal) {
    RelativeError e = relativeLuminanceError(actual, ideal);
    double logAverage = idealLuminance(ideal).logAverage;
    return {e.max, e.mean, psnr8(referenceToneMap(actual, logAverage), referenceToneMap(ideal, logAverage))};
}

ErrorMetrics luminanceStageMetrics(double actualLogAverage, double idealLogAverage, const LinearImage& sanitisedInput) {
    double floor = idealLogAverage > 0.0 ? 1e-3 * idealLogAverage : 1e-30;
    double e = relative(actualLogAverage, idealLogAverage, floor);
    double psnr = std::isfinite(actualLogAverage)
                      ? psnr8(referenceToneMap(sanitisedInput, actualLogAverage),
                              referenceToneMap(sanitisedInput, idealLogAverage))
                      : -kInfinity;
    return {e, e, psnr};
}

ErrorMetrics toneMapStageMetrics(const LinearImage& actual, const LinearImage& idealDisplay) {
    LinearImage actual8 = actual, decoded = actual;
    for (double& v : actual8.rgb) v = std::floor(std::clamp(v, 0.0, 1.0) * 255.0 + 0.5);
    for (double& v : decoded.rgb) v = srgbDecode(v);
    RelativeError e = relativeLuminanceError(decoded, idealDisplay, 1.0 / 255.0);
    return {e.max, e.mean, psnr8(actual8, eightBitSrgb(idealDisplay))};
}

}  // namespace rmfx::accuracy
