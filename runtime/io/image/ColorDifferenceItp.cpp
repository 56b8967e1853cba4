#include "io/image/ColorDifferenceItp.h"

#include <algorithm>
#include <cmath>

namespace rmfx {

namespace {

// BT.709 to BT.2020 primaries, both with the D65 white: BT.2087 gives this matrix rounded to
// four decimals; these digits are computed from the two sets of chromaticities.
constexpr double kBt709ToBt2020[3][3] = {
    {0.62740389593469903, 0.32928303837788370, 0.043313065687417225},
    {0.069097289358232075, 0.91954039507545871, 0.011362315566309178},
    {0.016391438875150280, 0.088013307877225749, 0.89559525324762401},
};

// SMPTE ST 2084's inverse EOTF: absolute luminance in cd/m² to the PQ signal (1 at 10 000 cd/m²).
double pqEncode(double luminance) {
    constexpr double m1 = 2610.0 / 16384, m2 = 2523.0 / 4096 * 128;
    constexpr double c1 = 3424.0 / 4096, c2 = 2413.0 / 4096 * 32, c3 = 2392.0 / 4096 * 32;
    double y = std::pow(std::max(luminance, 0.0) / 10000.0, m1);
    return std::pow((c1 + c2 * y) / (1.0 + c3 * y), m2);
}

}  // namespace

ItpColor itpFromBt2020(double r, double g, double b, double luminance) {
    // BT.2100's RGB to LMS, its integer coefficients over 4096; each row sums to 1, so a grey
    // has L = M = S and no chroma.
    double l = pqEncode(luminance * (1688 * r + 2146 * g + 262 * b) / 4096);
    double m = pqEncode(luminance * (683 * r + 2951 * g + 462 * b) / 4096);
    double s = pqEncode(luminance * (99 * r + 309 * g + 3688 * b) / 4096);
    double ct = (6610 * l - 13613 * m + 7003 * s) / 4096;
    double cp = (17933 * l - 17390 * m - 543 * s) / 4096;
    return {0.5 * l + 0.5 * m, 0.5 * ct, cp};
}

ItpColor itpFromBt709(double r, double g, double b, double luminance) {
    const auto& k = kBt709ToBt2020;
    return itpFromBt2020(k[0][0] * r + k[0][1] * g + k[0][2] * b, k[1][0] * r + k[1][1] * g + k[1][2] * b,
                         k[2][0] * r + k[2][1] * g + k[2][2] * b, luminance);
}

double deltaEItp(const ItpColor& a, const ItpColor& b) {
    double di = a.i - b.i, dt = a.t - b.t, dp = a.p - b.p;
    return 720.0 * std::sqrt(di * di + dt * dt + dp * dp);
}

}  // namespace rmfx
