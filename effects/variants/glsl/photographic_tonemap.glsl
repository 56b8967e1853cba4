#pragma once
// The tone map stage: Reinhard et al. 2002's photographic operator on luminance. With the scene's
// log-average Scene_Luminance mapped to Middle_Gray, L = Middle_Gray Y / max(Scene_Luminance, 1e-6),
// Ld = L (1 + L / White_Point²) / (1 + L), and each channel scaled by Ld / Y, clamped to [0, 1].
#include "stage_input.glsl"

uniform float Scene_Luminance;
uniform float Middle_Gray;
uniform float White_Point;

// L / Y; the 1e-6 floor keeps a black scene (Scene_Luminance 0) finite.
float luminanceScale() { return Middle_Gray / max(Scene_Luminance, 1e-6); }

// Ld / L = (1 + L / White²) / (1 + L) written as 1 / (1 + L) + (L / (1 + L)) / White²: two positive
// terms, each finite for any L (up to the float maximum), so the curve never gives Inf / Inf.
float photographicRatio(float l) {
    float white2 = max(White_Point * White_Point, 1e-12);
    return 1.0 / (1.0 + l) + (l / (1.0 + l)) / white2;
}

// The LUT variants' table: `entries` values of Ld / L at log2(L) = -12 .. 12, entry i at
// -12 + 24 i / (entries - 1); outside that range the end entries hold.
const float CURVE_LUT_MIN_LOG2 = -12.0;
const float CURVE_LUT_MAX_LOG2 = 12.0;
float curveLutLog2(int entry, int entries) {
    return CURVE_LUT_MIN_LOG2 + (CURVE_LUT_MAX_LOG2 - CURVE_LUT_MIN_LOG2) * float(entry) / float(max(entries - 1, 1));
}
// Where a linearly filtered lookup of a table `entries` texels wide finds log2(L) = log2L.
float curveLutCoordinate(float log2L, int entries) {
    float t = clamp((log2L - CURVE_LUT_MIN_LOG2) / (CURVE_LUT_MAX_LOG2 - CURVE_LUT_MIN_LOG2), 0.0, 1.0);
    return (t * float(entries - 1) + 0.5) / float(entries);
}

// The scaled luminance of a colour, or 0 where Y is 0; at most the float maximum (an overflow to
// +Inf would give Inf / Inf further on).
float scaledLuminance(vec3 rgb) {
    float y = rec709Luminance(rgb);
    return y > 0.0 ? min(y * luminanceScale(), 3.40282347e38) : 0.0;
}

// rgb · Ld / Y = rgb · (L / Y) · (Ld / L), clamped: every factor is finite and non-negative.
vec3 toneMapped(vec3 rgb, float ratio) {
    if (!(rec709Luminance(rgb) > 0.0)) return vec3(0.0);
    return clamp(rgb * (luminanceScale() * ratio), 0.0, 1.0);
}

// The sRGB OETF, exact (IEC 61966-2-1).
vec3 srgbEncode(vec3 c) {
    return mix(12.92 * c, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, greaterThan(c, vec3(0.0031308)));
}
