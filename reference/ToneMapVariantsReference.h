#pragma once
// Float64 reference of the tone map stage (effects/variants/tonemap.xml), from issue 7's contract:
// L = Middle_Gray Y / max(Scene_Luminance, 1e-6), Ld = L (1 + L / White_Point²) / (1 + L),
// rgb · Ld / Y clamped to [0, 1] (0 where Y = 0), then the display encoding; and models of the
// variants' own maths (sqrt for the sRGB OETF, Ld / L from a linearly interpolated table).

#include <glm/vec3.hpp>

namespace rmfx::test {

struct ToneMapSettings {
    double sceneLuminance = 0.18;
    double middleGray = 0.18;
    double whitePoint = 4.0;
};

enum class ToneMapCurve { Analytic, FastGamma, Lut256, Lut32 };

// Ld / L, exactly.
double photographicRatio(double l, double whitePoint);
// Ld / L as the LUT variants find it: `entries` values at log2(L) = -12 + 24 i / (entries - 1),
// linearly interpolated, the end values beyond.
double tableRatio(double l, double whitePoint, int entries);

// The display value of each channel (0..1, before 8-bit rounding) of a stored HDR colour (S ·
// Exposure as the hdr target holds it), by a curve variant; Analytic is the ideal.
glm::dvec3 toneMapped(glm::dvec3 hdr, const ToneMapSettings& settings, ToneMapCurve curve);

double srgbOetf(double linear);

}  // namespace rmfx::test
