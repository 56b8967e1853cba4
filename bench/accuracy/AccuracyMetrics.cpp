#include "bench/accuracy/AccuracyMetrics.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

#include "reference/IdealLuminance.h"
#include "reference/IdealToneMap.h"
#include "reference/StageInput.h"

namespace rmfx::accuracy {
namespace {

using test::RefImage;

constexpr double kInfinity = std::numeric_limits<double>::infinity();

double luminanceAt(const RefImage& image, int x, int y) { return test::rec709Luminance(glm::dvec3(image.at(x, y))); }

double relative(double actual, double ideal, double floor) {
    double e = std::abs(actual - ideal) / std::max(ideal, floor);
    return std::isfinite(e) ? e : kInfinity;
}

}  // namespace

RelativeError relativeLuminanceError(const RefImage& actual, const RefImage& ideal, std::optional<double> floor) {
    assert(actual.width == ideal.width && actual.height == ideal.height);
    RelativeError out;
    const size_t n = ideal.texels.size();
    if (n == 0) return out;
    // The sums run from the top row down (rows are bottom-up), the order they have always taken.
    if (!floor) {
        double sum = 0.0;
        for (int y = ideal.height - 1; y >= 0; --y)
            for (int x = 0; x < ideal.width; ++x) sum += luminanceAt(ideal, x, y);
        double f = 1e-3 * sum / static_cast<double>(n);
        floor = f > 0.0 ? f : 1e-30;
    }
    double total = 0.0;
    for (int y = ideal.height - 1; y >= 0; --y)
        for (int x = 0; x < ideal.width; ++x) {
            double e = relative(luminanceAt(actual, x, y), luminanceAt(ideal, x, y), *floor);
            out.max = std::max(out.max, e);
            total += e;
        }
    out.mean = total / static_cast<double>(n);
    return out;
}

double psnr8(const RefImage& a, const RefImage& b) {
    assert(a.width == b.width && a.height == b.height);
    if (a.texels.empty()) return kInfinity;
    double sum = 0.0;
    for (int y = a.height - 1; y >= 0; --y)  // from the top row down, as relativeLuminanceError
        for (int x = 0; x < a.width; ++x)
            for (int c = 0; c < 3; ++c) sum += (a.at(x, y)[c] - b.at(x, y)[c]) * (a.at(x, y)[c] - b.at(x, y)[c]);
    double mse = sum / static_cast<double>(3 * a.texels.size());
    if (std::isnan(mse)) return -kInfinity;
    return mse == 0.0 ? kInfinity : 10.0 * std::log10(255.0 * 255.0 / mse);
}

RefImage referenceToneMap(const RefImage& image, double logAverage) {
    test::ToneMapParameters p;
    p.sceneLuminance = logAverage;
    p.middleGray = 0.18;
    p.whitePoint = 4.0;
    p.exposure = 1.0;
    return test::idealToneMap(image, p);
}

ErrorMetrics imageStageMetrics(const RefImage& actual, const RefImage& ideal) {
    RelativeError e = relativeLuminanceError(actual, ideal);
    double logAverage = test::idealLuminance(ideal).logAverage;
    return {e.max, e.mean, psnr8(referenceToneMap(actual, logAverage), referenceToneMap(ideal, logAverage))};
}

ErrorMetrics luminanceStageMetrics(double actualLogAverage, double idealLogAverage, const RefImage& sanitisedInput) {
    double floor = idealLogAverage > 0.0 ? 1e-3 * idealLogAverage : 1e-30;
    double e = relative(actualLogAverage, idealLogAverage, floor);
    double psnr = std::isfinite(actualLogAverage)
                      ? psnr8(referenceToneMap(sanitisedInput, actualLogAverage),
                              referenceToneMap(sanitisedInput, idealLogAverage))
                      : -kInfinity;
    return {e, e, psnr};
}

ErrorMetrics toneMapStageMetrics(const RefImage& actual, const RefImage& idealDisplay) {
    RefImage actual8 = actual, decoded = actual;
    for (glm::dvec4& t : actual8.texels)
        for (int c = 0; c < 3; ++c) t[c] = std::floor(std::clamp(t[c], 0.0, 1.0) * 255.0 + 0.5);
    for (glm::dvec4& t : decoded.texels)
        for (int c = 0; c < 3; ++c) t[c] = test::srgbDecode(t[c]);
    RelativeError e = relativeLuminanceError(decoded, idealDisplay, 1.0 / 255.0);
    return {e.max, e.mean, psnr8(actual8, test::eightBitSrgb(idealDisplay))};
}

}  // namespace rmfx::accuracy
