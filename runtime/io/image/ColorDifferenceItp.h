#pragma once
// ΔE_ITP, the colour difference of Recommendation ITU-R BT.2124 for HDR and wide-gamut images:
//
//   linear RGB, BT.709 primaries (rmfx's images)  → linear RGB, BT.2020 primaries (BT.2087)
//   → LMS (the BT.2100 matrix) → L′M′S′ by the PQ inverse EOTF (SMPTE ST 2084) of absolute luminance
//   → ICtCp (BT.2100) → ITP with T = Ct / 2, P = Cp
//   ΔE_ITP = 720·√(ΔI² + ΔT² + ΔP²)
//
// A ΔE_ITP of 1 is about one just noticeable difference. PQ encodes absolute luminance, so a
// colour needs a scale: `luminance` is how many cd/m² a value of 1.0 stands for.

namespace rmfx {

// cd/m² of 1.0 unless a compare says otherwise: SDR reference white.
inline constexpr double kItpDefaultLuminance = 100.0;

struct ItpColor {
    double i = 0;  // intensity: PQ-encoded
    double t = 0;  // tritan (blue–yellow): Ct / 2
    double p = 0;  // protan (red–green): Cp
};

// Finite linear RGB. LMS below 0 (light no display emits) is taken as 0. Above 10 000 cd/m²,
// PQ's range, its formula is continued as written: it still grows (towards 2), so differences
// there still count, compressed.
ItpColor itpFromBt709(double r, double g, double b, double luminance);
ItpColor itpFromBt2020(double r, double g, double b, double luminance);

double deltaEItp(const ItpColor& a, const ItpColor& b);

}  // namespace rmfx
