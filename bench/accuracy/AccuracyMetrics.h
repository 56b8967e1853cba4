#pragma once
// How far a variant's result is from its stage's ideal (docs/accuracy-vs-time.md, "Metrics"):
// relative luminance error per pixel, its max and mean, and the PSNR of 8-bit tone-mapped images.
// Images are test::RefImage (reference/CpuImage.h, row 0 at the bottom); only rgb counts.

#include <optional>

#include "reference/CpuImage.h"

namespace rmfx::accuracy {

struct ErrorMetrics {
    double maxRelative = 0.0;
    double meanRelative = 0.0;
    double psnrDb = 0.0;  // +inf for identical 8-bit images
};

struct RelativeError {
    double max = 0.0;
    double mean = 0.0;
};

// |Y − Y*| / max(Y*, floor) per pixel (Rec.709 Y), its max and mean. Default floor:
// 1e-3 · mean(Y*), or 1e-30 when that is 0. A pixel whose error is not finite (NaN in `actual`)
// counts as +inf. The sizes must match.
RelativeError relativeLuminanceError(const test::RefImage& actual, const test::RefImage& ideal,
                                     std::optional<double> floor = std::nullopt);

// 10 log10(255² / MSE) over the r, g, b values (0..255) of two 8-bit images; +inf when equal.
double psnr8(const test::RefImage& a, const test::RefImage& b);

// The tone map the PSNR compares through: Reinhard photographic with key 0.18, white point 4,
// scene luminance `logAverage`, sRGB, 8 bits (reference/IdealToneMap.h with those parameters).
test::RefImage referenceToneMap(const test::RefImage& image, double logAverage);

// Bloom and streak: relative error of the result, PSNR of both through referenceToneMap with the
// exact log-average of the ideal.
ErrorMetrics imageStageMetrics(const test::RefImage& actual, const test::RefImage& ideal);

// Luminance: relative error of the log-average (max = mean), PSNR of the input tone-mapped with
// the variant's log-average against the input tone-mapped with the ideal's.
ErrorMetrics luminanceStageMetrics(double actualLogAverage, double idealLogAverage,
                                  const test::RefImage& sanitisedInput);

// Tone map: `actual` holds the rgba8 output as read back (k / 255, sRGB-encoded); `idealDisplay`
// the ideal's display values before the OETF (toneMapDisplay). PSNR of the 8-bit images, and the
// relative luminance error of the sRGB-decoded output against the display values, floor 1/255.
ErrorMetrics toneMapStageMetrics(const test::RefImage& actual, const test::RefImage& idealDisplay);

}  // namespace rmfx::accuracy
