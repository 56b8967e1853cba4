// ΔE_ITP (ITU-R BT.2124) against a float64 computation written here from the standards: the
// BT.709 → BT.2020 matrix derived from the primaries' chromaticities, and PQ through ST 2084's
// EOTF (signal → luminance), inverted by bisection rather than by the inverse EOTF's formula.
// Then published values, and the metric's properties: 0 for equal colours, symmetry, growth
// with the difference, and about 1 at a just noticeable difference.

#include "io/image/ColorDifferenceItp.h"

#include <array>
#include <cmath>

#include <gtest/gtest.h>

namespace rmfx {
namespace {

using Vec3 = std::array<double, 3>;
using Mat3 = std::array<Vec3, 3>;

Vec3 times(const Mat3& m, const Vec3& v) {
    return {m[0][0] * v[0] + m[0][1] * v[1] + m[0][2] * v[2], m[1][0] * v[0] + m[1][1] * v[1] + m[1][2] * v[2],
            m[2][0] * v[0] + m[2][1] * v[1] + m[2][2] * v[2]};
}

Mat3 product(const Mat3& a, const Mat3& b) {
    Mat3 out{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            for (int k = 0; k < 3; ++k) out[i][j] += a[i][k] * b[k][j];
    return out;
}

Mat3 inverse(const Mat3& m) {
    double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                 m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    Mat3 out;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            // The cofactor of m[j][i], from the rows and columns cyclically after it.
            int r0 = (j + 1) % 3, r1 = (j + 2) % 3, c0 = (i + 1) % 3, c1 = (i + 2) % 3;
            out[i][j] = (m[r0][c0] * m[r1][c1] - m[r0][c1] * m[r1][c0]) / det;
        }
    return out;
}

// RGB → XYZ of primaries with chromaticities (x, y), scaled so that RGB 1 is the D65 white at Y = 1.
Mat3 rgbToXyz(const std::array<std::array<double, 2>, 3>& primaries) {
    const double wx = 0.3127, wy = 0.3290;
    Mat3 columns;
    for (int c = 0; c < 3; ++c) {
        auto [x, y] = primaries[c];
        columns[0][c] = x / y;
        columns[1][c] = 1.0;
        columns[2][c] = (1 - x - y) / y;
    }
    Vec3 scale = times(inverse(columns), {wx / wy, 1.0, (1 - wx - wy) / wy});
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) columns[r][c] *= scale[c];
    return columns;
}

const Mat3 kReference709To2020 = product(inverse(rgbToXyz({{{0.708, 0.292}, {0.170, 0.797}, {0.131, 0.046}}})),
                                         rgbToXyz({{{0.64, 0.33}, {0.30, 0.60}, {0.15, 0.06}}}));

// SMPTE ST 2084's EOTF: PQ signal → cd/m². Defined for signals up to (c2 / c3)^m2 ≈ 1.99, where
// the luminance grows without bound.
constexpr double m1 = 0.1593017578125, m2 = 78.84375, c1 = 0.8359375, c2 = 18.8515625, c3 = 18.6875;
const double kSignalLimit = std::pow(c2 / c3, m2);

double pqLuminance(double signal) {
    double e = std::pow(signal, 1 / m2);
    return 10000 * std::pow(std::max(e - c1, 0.0) / (c2 - c3 * e), 1 / m1);
}

// The largest signal the EOTF takes to `cdm2`: signals up to c1^m2 all show 0 cd/m².
double pqSignal(double cdm2) {
    double low = 0, high = kSignalLimit;
    for (int i = 0; i < 200; ++i) {
        double mid = 0.5 * (low + high);
        (pqLuminance(mid) <= cdm2 ? low : high) = mid;
    }
    return 0.5 * (low + high);
}

// ITP of linear BT.709 RGB with 1.0 = `luminance` cd/m².
Vec3 referenceItp(const Vec3& rgb709, double luminance) {
    Vec3 rgb = times(kReference709To2020, rgb709);
    const Mat3 toLms = {{{1688 / 4096.0, 2146 / 4096.0, 262 / 4096.0},
                         {683 / 4096.0, 2951 / 4096.0, 462 / 4096.0},
                         {99 / 4096.0, 309 / 4096.0, 3688 / 4096.0}}};
    Vec3 lms = times(toLms, rgb);
    Vec3 encoded;
    for (int c = 0; c < 3; ++c) encoded[c] = lms[c] <= 0 ? pqSignal(0) : pqSignal(lms[c] * luminance);
    const Mat3 toIctcp = {{{0.5, 0.5, 0.0},
                           {6610 / 4096.0, -13613 / 4096.0, 7003 / 4096.0},
                           {17933 / 4096.0, -17390 / 4096.0, -543 / 4096.0}}};
    Vec3 ictcp = times(toIctcp, encoded);
    return {ictcp[0], ictcp[1] / 2, ictcp[2]};
}

double referenceDeltaE(const Vec3& a, const Vec3& b, double luminance) {
    Vec3 x = referenceItp(a, luminance), y = referenceItp(b, luminance);
    return 720 * std::hypot(x[0] - y[0], x[1] - y[1], x[2] - y[2]);
}

double deltaE(const Vec3& a, const Vec3& b, double luminance = kItpDefaultLuminance) {
    return deltaEItp(itpFromBt709(a[0], a[1], a[2], luminance), itpFromBt709(b[0], b[1], b[2], luminance));
}

TEST(ColorDifferenceItp, MatchesTheFloat64ComputationFromTheStandards) {
    struct Pair {
        Vec3 a, b;
        double luminance;
    };
    const Pair pairs[] = {
        {{0.5, 0.5, 0.5}, {0.52, 0.5, 0.5}, 100},
        {{0.18, 0.18, 0.18}, {0.18, 0.18, 0.19}, 100},
        {{1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, 100},
        {{0.2, 0.4, 0.8}, {0.25, 0.35, 0.7}, 203},
        {{0.01, 0.002, 0.03}, {0.012, 0.002, 0.028}, 100},
        {{10.0, 8.0, 6.0}, {10.0, 8.5, 6.0}, 100},      // HDR: 1000 cd/m² for 10
        {{1000.0, 1000.0, 1000.0}, {800.0, 900.0, 1000.0}, 100},  // 10⁵ cd/m²: beyond PQ's 10 000
        {{10.0, 10.0, 10.0}, {1000.0, 1000.0, 1000.0}, 100},
        {{0.3, 0.6, 0.1}, {0.3, 0.6, 0.1}, 1000},
        {{0.0, 0.0, 0.0}, {0.001, 0.0, 0.0}, 100},
    };
    for (const Pair& p : pairs) {
        double expected = referenceDeltaE(p.a, p.b, p.luminance);
        EXPECT_NEAR(deltaE(p.a, p.b, p.luminance), expected, 1e-9 * std::max(1.0, expected))
            << p.a[0] << " " << p.a[1] << " " << p.a[2] << " against " << p.b[0] << " " << p.b[1] << " " << p.b[2];
        ItpColor itp = itpFromBt709(p.a[0], p.a[1], p.a[2], p.luminance);
        Vec3 reference = referenceItp(p.a, p.luminance);
        EXPECT_NEAR(itp.i, reference[0], 1e-12);
        EXPECT_NEAR(itp.t, reference[1], 1e-12);
        EXPECT_NEAR(itp.p, reference[2], 1e-12);
    }
    EXPECT_GT(deltaE({10, 8, 6}, {10, 8.5, 6}), 1);
    // Above PQ's range differences still count.
    EXPECT_GT(deltaE({1000, 1000, 1000}, {800, 900, 1000}), 1);
}

// The examples in colour-science's documentation (colour.readthedocs.io): RGB_to_ICTCP (BT.2020
// RGB in cd/m², so 1.0 = 1 cd/m² here) and delta_E_ITP (from ICtCp: T = Ct / 2 here).
TEST(ColorDifferenceItp, PublishedExamples) {
    ItpColor a = itpFromBt2020(0.45620519, 0.03081071, 0.04091952, 1.0);
    EXPECT_NEAR(a.i, 0.07351364, 1e-8);
    EXPECT_NEAR(a.t, 0.00475253 / 2, 1e-8);
    EXPECT_NEAR(a.p, 0.09351596, 1e-8);
    ItpColor b = itpFromBt2020(0.35181454, 0.26934757, 0.21288023, 1.0);
    EXPECT_NEAR(b.i, 0.09554079, 1e-8);
    EXPECT_NEAR(b.t, -0.00890639 / 2, 1e-8);
    EXPECT_NEAR(b.p, 0.01389286, 1e-8);

    ItpColor x{0.4885468072, -0.04739350675 / 2, 0.07475401302};
    ItpColor y{0.4899203231, -0.04567508203 / 2, 0.07361341775};
    EXPECT_NEAR(deltaEItp(x, y), 1.42657228, 1e-8);
}

TEST(ColorDifferenceItp, ZeroForEqualColoursAndSymmetric) {
    const Vec3 colours[] = {{0, 0, 0}, {0.5, 0.25, 0.125}, {1, 1, 1}, {10, 2, 0.5}, {1000, 0, 0}};
    for (const Vec3& a : colours) {
        EXPECT_EQ(deltaE(a, a), 0.0);
        for (const Vec3& b : colours) EXPECT_EQ(deltaE(a, b), deltaE(b, a));
    }
}

TEST(ColorDifferenceItp, GreysHaveNoChroma) {
    for (double v : {0.001, 0.18, 1.0, 10.0, 1000.0}) {
        ItpColor grey = itpFromBt709(v, v, v, kItpDefaultLuminance);
        EXPECT_NEAR(grey.t, 0.0, 1e-12) << v;
        EXPECT_NEAR(grey.p, 0.0, 1e-12) << v;
        EXPECT_NEAR(grey.i, pqSignal(v * kItpDefaultLuminance), 1e-12) << v;
    }
}

TEST(ColorDifferenceItp, GrowsWithTheDifference) {
    struct Direction {
        Vec3 base, step;
    };
    const Direction directions[] = {
        {{0.5, 0.5, 0.5}, {0.01, 0.01, 0.01}},   // lighter
        {{0.5, 0.5, 0.5}, {0.01, -0.01, 0}},     // redder
        {{0.2, 0.3, 0.4}, {0, 0, 0.02}},         // bluer
        {{10, 10, 10}, {-0.2, 0, 0.2}},          // HDR
        {{500, 500, 500}, {50, 50, 50}},         // beyond PQ's range
    };
    for (const Direction& d : directions) {
        double previous = 0;
        for (int k = 1; k <= 20; ++k) {
            Vec3 other{d.base[0] + k * d.step[0], d.base[1] + k * d.step[1], d.base[2] + k * d.step[2]};
            double e = deltaE(d.base, other);
            EXPECT_GT(e, previous) << "step " << k << " from " << d.base[0];
            previous = e;
        }
    }
}

// BT.2124 scales ΔE_ITP so that 1 is about one just noticeable difference. On a grey of
// 100 cd/m² the step that gives 1 is a Weber fraction ΔL/L of 1.39 %; luminance discrimination
// at such levels needs 1 % to 2 % (Weber's 1/100, Bouguer's 1/64; telescope-optics.net,
// "Eye intensity response, contrast sensitivity").
TEST(ColorDifferenceItp, AboutOneAtAJustNoticeableDifference) {
    double low = 0, high = 0.1;
    for (int i = 0; i < 100; ++i) {
        double mid = 0.5 * (low + high);
        (deltaE({1, 1, 1}, {1 + mid, 1 + mid, 1 + mid}) < 1 ? low : high) = mid;
    }
    double weber = 0.5 * (low + high);
    EXPECT_NEAR(weber, 0.0139, 0.0001);
    EXPECT_GT(weber, 1.0 / 100);
    EXPECT_LT(weber, 2.0 / 100);
    // The float64 computation agrees on that step.
    EXPECT_NEAR(referenceDeltaE({1, 1, 1}, {1 + weber, 1 + weber, 1 + weber}, 100), 1.0, 1e-9);
}

TEST(ColorDifferenceItp, NegativeLightIsBlack) {
    ItpColor black = itpFromBt709(0, 0, 0, kItpDefaultLuminance);
    ItpColor negative = itpFromBt709(-1, -0.5, -2, kItpDefaultLuminance);
    EXPECT_EQ(negative.i, black.i);
    EXPECT_EQ(negative.t, black.t);
    EXPECT_EQ(negative.p, black.p);
    // The clamp is of LMS, not of RGB: a BT.709 channel below 0 is a colour outside BT.709 that
    // BT.2020 and LMS may still hold, and it differs from the colour with that channel at 0.
    Vec3 outside709{-0.02, 0.5, 0.5};
    EXPECT_GT(deltaE(outside709, {0, 0.5, 0.5}), 1);
    EXPECT_NEAR(deltaE(outside709, {0, 0.5, 0.5}), referenceDeltaE(outside709, {0, 0.5, 0.5}, 100), 1e-9);
}

}  // namespace
}  // namespace rmfx
