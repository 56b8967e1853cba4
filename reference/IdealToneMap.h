#pragma once
// The tone-map stage's ideal (effects/variants/tonemap.xml), also the reference tone map of the
// bench's error metrics: Reinhard's photographic operator with a white point. For S · Exposure
// with luminance Y: L = Middle_Gray · Y / max(Scene_Luminance, 1e-6), Ld = L (1 + L / W²) / (1 + L),
// display rgb = clamp(rgb · Ld / Y, 0, 1) (0 where Y = 0), then the exact sRGB OETF and 8 bits.
// Float64 on rgb; alpha is not used.

#include "reference/CpuImage.h"

namespace rmfx::test {

struct ToneMapParameters {
    double sceneLuminance = 0.18;
    double middleGray = 0.18;
    double whitePoint = 4.0;
    double exposure = 1.0;
};

// The display values: linear, in [0, 1], before the sRGB OETF.
RefImage toneMapDisplay(const RefImage& sanitised, const ToneMapParameters& p);

// IEC 61966-2-1 in float64.
double srgbEncode(double linear);
double srgbDecode(double encoded);

// Each rgb channel sRGB-encoded and rounded to 8 bits: values 0..255 (whole numbers).
RefImage eightBitSrgb(const RefImage& display);

// toneMapDisplay then eightBitSrgb.
RefImage idealToneMap(const RefImage& sanitised, const ToneMapParameters& p);

}  // namespace rmfx::test
