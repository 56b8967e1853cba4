// The float64 ideals `rmfx bench` measures the variants against (reference/Ideal*.h), against
// cases derived by hand: the Gaussian of an impulse is the sampled normalised Gaussian, the streak
// of an impulse (1 − w) w^k along each diagonal, the log-average of a two-value image
// sqrt((δ + a)(δ + b)), and the tone map of grey values Ld = L (1 + L / W²) / (1 + L).

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "reference/IdealBloom.h"
#include "reference/IdealLuminance.h"
#include "reference/IdealStreak.h"
#include "reference/IdealToneMap.h"
#include "reference/StageInput.h"

namespace rmfx::test {
namespace {

RefImage grey(int w, int h, double v) { return RefImage(w, h, glm::dvec4(v, v, v, 0.0)); }

void setGrey(RefImage& image, int x, int y, double v) { image.at(x, y) = glm::dvec4(v, v, v, 0.0); }

TEST(AccuracyIdeals, SanitisingZeroesNanInfAndNegatives) {
    Image in{2, 1, 4, true, 32, {std::numeric_limits<float>::quiet_NaN(), -1.0f, 2.0f, 9.0f,
                                 std::numeric_limits<float>::infinity(), 0.5f, -std::numeric_limits<float>::infinity(), 1.0f}};
    RefImage s = sanitisedInput(in);
    EXPECT_EQ(s.at(0, 0)[0], 0.0);
    EXPECT_EQ(s.at(0, 0)[1], 0.0);
    EXPECT_EQ(s.at(0, 0)[2], 2.0);
    EXPECT_EQ(s.at(1, 0)[0], 0.0);
    EXPECT_EQ(s.at(1, 0)[1], 0.5);
    EXPECT_EQ(s.at(1, 0)[2], 0.0);
}

TEST(AccuracyIdeals, SanitisedInputHasRowZeroAtTheBottom) {
    Image in{1, 2, 1, true, 32, {1.0f, 2.0f}};  // one channel: row 0 (the top) 1, the bottom row 2
    RefImage s = sanitisedInput(in);
    EXPECT_EQ(s.at(0, 0), glm::dvec4(2.0, 2.0, 2.0, 1.0));
    EXPECT_EQ(s.at(0, 1), glm::dvec4(1.0, 1.0, 1.0, 1.0));
}

TEST(AccuracyIdeals, GaussianKernelIsTheSampledGaussianNormalisedOverFourSigma) {
    std::vector<double> k = gaussianKernel(1.5);  // radius ceil(6) = 6
    ASSERT_EQ(k.size(), 13u);
    double sum = 0.0;
    for (int i = -6; i <= 6; ++i) sum += std::exp(-i * i / (2 * 2.25));
    for (int i = -6; i <= 6; ++i) EXPECT_NEAR(k[i + 6], std::exp(-i * i / 4.5) / sum, 1e-15) << i;
    EXPECT_EQ(gaussianKernel(0.0), std::vector<double>{1.0});
}

TEST(AccuracyIdeals, BloomOfAnImpulseIsTheGaussianAroundIt) {
    const int n = 41;
    RefImage s(n, n);
    setGrey(s, 20, 20, 11.0);  // B = 10 at the centre, 0 elsewhere (threshold 1)
    BloomParameters p{1.0, 0.5, 2.0 / n};  // sigma 2 pixels, radius 8
    RefImage out = idealBloom(s, p);
    double sum = 0.0;
    for (int i = -8; i <= 8; ++i) sum += std::exp(-i * i / 8.0);
    double bloomTotal = 0.0;
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            int dx = x - 20, dy = y - 20;
            double g = std::abs(dx) <= 8 && std::abs(dy) <= 8
                           ? std::exp(-dx * dx / 8.0) / sum * std::exp(-dy * dy / 8.0) / sum
                           : 0.0;
            double expected = (x == 20 && y == 20 ? 11.0 : 0.0) + 0.5 * 10.0 * g;
            ASSERT_NEAR(out.at(x, y)[1], expected, 1e-12) << x << "," << y;
            bloomTotal += out.at(x, y)[0] - s.at(x, y)[0];
        }
    EXPECT_NEAR(bloomTotal, 5.0, 1e-12);  // nothing lost inside the image
}

TEST(AccuracyIdeals, BloomIsBlackOutsideTheImage) {
    RefImage s(9, 9);
    setGrey(s, 0, 0, 3.0);  // B = 2 at a corner: three quarters of its blur fall outside
    RefImage out = idealBloom(s, {1.0, 1.0, 1.0 / 9});
    double total = 0.0;
    for (int y = 0; y < 9; ++y)
        for (int x = 0; x < 9; ++x) total += out.at(x, y)[0] - s.at(x, y)[0];
    std::vector<double> k = gaussianKernel(1.0);
    double half = 0.0;
    for (size_t i = k.size() / 2; i < k.size(); ++i) half += k[i];
    EXPECT_NEAR(total, 2.0 * half * half, 1e-12);
}

TEST(AccuracyIdeals, StreakOfAnImpulseDecaysAsOneMinusWTimesWToTheK) {
    const int n = 9;
    RefImage s = grey(n, n, 0.25);  // below the threshold: only the impulse streaks
    setGrey(s, 4, 4, 9.0);            // B = 8
    StreakParameters p{1.0, 0.5, 0.5};
    double w = std::exp(-1.0 / (0.5 * n));
    EXPECT_NEAR(streakDecay(0.5, n), w, 1e-15);
    RefImage out = idealStreak(s, p);
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            int dx = x - 4, dy = y - 4;
            double expected = s.at(x, y)[0];
            if (dx == 0 && dy == 0) expected += 0.5 * (1 - w) * 8.0;  // all four directions
            else if (std::abs(dx) == std::abs(dy)) expected += 0.5 * 0.25 * (1 - w) * std::pow(w, std::abs(dx)) * 8.0;
            ASSERT_NEAR(out.at(x, y)[2], expected, 1e-12) << x << "," << y;
        }
}

TEST(AccuracyIdeals, StreakAlongOneDirectionGathersFromAheadOnly) {
    RefImage b(5, 5);
    setGrey(b, 3, 1, 1.0);
    double w = 0.5;
    RefImage s = streakAlong(b, 1, 1, w);  // s(x) sums B(x + k (1, 1))
    EXPECT_NEAR(s.at(3, 1)[0], 0.5, 1e-15);
    EXPECT_NEAR(s.at(2, 0)[0], 0.25, 1e-15);
    EXPECT_EQ(s.at(4, 2)[0], 0.0);
    EXPECT_EQ(s.at(1, 1)[0], 0.0);
}

TEST(AccuracyIdeals, LogAverageOfTwoValuesIsTheGeometricMeanOfDeltaPlusEach) {
    RefImage s(4, 2);
    for (int x = 0; x < 4; ++x) setGrey(s, x, 0, 0.02), setGrey(s, x, 1, 50.0);  // grey: Y = value
    SceneLuminance l = idealLuminance(s, 1e-4);
    EXPECT_NEAR(l.logAverage, std::sqrt((1e-4 + 0.02) * (1e-4 + 50.0)), 1e-12);
    EXPECT_NEAR(l.largest, 50.0, 1e-12);
    EXPECT_NEAR(idealLuminance(RefImage(3, 3)).logAverage, 1e-4, 1e-18);  // black: delta
}

TEST(AccuracyIdeals, ToneMapOfGreyValuesFollowsReinhardWithWhitePoint) {
    RefImage s(4, 1);
    setGrey(s, 0, 0, 1.0);
    setGrey(s, 1, 0, 4.0);  // at the white point: 1
    setGrey(s, 2, 0, 0.0);
    s.at(3, 0)[0] = 8.0;  // saturated red: clamped to 1, g = b = 0
    ToneMapParameters p{0.18, 0.18, 4.0, 1.0};
    RefImage display = toneMapDisplay(s, p);
    EXPECT_NEAR(display.at(0, 0)[1], 0.53125, 1e-15);  // 1 · (1 + 1/16) / 2
    EXPECT_NEAR(display.at(1, 0)[0], 1.0, 1e-15);
    EXPECT_EQ(display.at(2, 0)[0], 0.0);
    EXPECT_EQ(display.at(3, 0)[0], 1.0);
    EXPECT_EQ(display.at(3, 0)[1], 0.0);
    RefImage eight = idealToneMap(s, p);
    // (1.055 · 0.53125^(1/2.4) − 0.055) · 255 = 192.67
    EXPECT_EQ(eight.at(0, 0)[0], 193.0);
    EXPECT_EQ(eight.at(1, 0)[2], 255.0);
    EXPECT_EQ(eight.at(2, 0)[2], 0.0);
    // Scene luminance and exposure scale L: exposure 2 at scene luminance 0.36 is the same image.
    RefImage same = toneMapDisplay(s, {0.36, 0.18, 4.0, 2.0});
    EXPECT_LE(maxAbsDifference(same, display, 3), 1e-15);
}

TEST(AccuracyIdeals, SrgbTransferFunctionsInvertEachOther) {
    EXPECT_NEAR(srgbEncode(0.002), 12.92 * 0.002, 1e-15);
    EXPECT_NEAR(srgbEncode(1.0), 1.0, 1e-15);
    for (double v : {0.0, 0.001, 0.2, 0.9}) EXPECT_NEAR(srgbDecode(srgbEncode(v)), v, 1e-14);
}

}  // namespace
}  // namespace rmfx::test
