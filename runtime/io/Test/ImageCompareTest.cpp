// compareImages against metrics computed by hand. The values are binary fractions, so every
// absolute and relative error below is exact in float. ΔE_ITP is tested on greys, whose ΔE_ITP
// is 720·|PQ(a) − PQ(b)| (ColorDifferenceItpTest tests colours).

#include "io/image/ImageCompare.h"

#include <cmath>
#include <cstdio>
#include <limits>

#include <gtest/gtest.h>

namespace rmfx {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

Image image(int width, int height, int channels, std::vector<float> pixels) {
    Image out;
    out.width = width;
    out.height = height;
    out.channels = channels;
    out.highDynamicRange = true;
    out.pixels = std::move(pixels);
    return out;
}

CompareLimits limits(std::optional<double> max, std::optional<double> mean, std::optional<double> pixel = {},
                     double failFraction = 0) {
    CompareLimits l;
    l.max = max;
    l.mean = mean;
    l.pixel = pixel;
    l.failFraction = failFraction;
    return l;
}

// 2x2, two channels. Absolute errors: pixel (0,0) 0 and 0.25, pixel (1,0) 0 and 0.125, the
// bottom row 0: max 0.25 at x=0 y=0 channel 1, mean 0.375 / 8 = 0.046875.
const Image kActual = image(2, 2, 2, {0.5f, 0.25f, 1.0f, 1.0f, 0.0f, 0.0f, 0.75f, 0.5f});
const Image kReference = image(2, 2, 2, {0.5f, 0.5f, 1.0f, 0.875f, 0.0f, 0.0f, 0.75f, 0.5f});

TEST(ImageCompare, AbsoluteErrorMaximumMeanAndWhere) {
    ImageComparison r = compareImages(kActual, kReference, limits(0.25, 0.04));
    EXPECT_EQ(r.problem, "");
    EXPECT_DOUBLE_EQ(r.metrics.maxError, 0.25);
    EXPECT_EQ(r.metrics.maxX, 0);
    EXPECT_EQ(r.metrics.maxY, 0);
    EXPECT_EQ(r.metrics.maxChannel, 1);
    EXPECT_DOUBLE_EQ(r.metrics.meanError, 0.046875);
    EXPECT_EQ(r.metrics.pixelCount, 4);
    EXPECT_EQ(r.metrics.failingPixels, 0);  // no pixel threshold given
    ASSERT_EQ(r.checks.size(), 2u);
    EXPECT_TRUE(r.checks[0].passed());   // max 0.25 ≤ 0.25: a limit is inclusive
    EXPECT_FALSE(r.checks[1].passed());  // mean 0.046875 > 0.04
    EXPECT_FALSE(r.passed());
    EXPECT_EQ(r.describe(), "max error 0.25 ≤ 0.25 at x=0 y=0 channel 1; mean error 0.046875 > 0.04");
    // The difference image holds |a − b| per channel.
    ASSERT_EQ(r.difference.width, 2);
    ASSERT_EQ(r.difference.channels, 2);
    EXPECT_EQ(r.difference.pixels, (std::vector<float>{0, 0.25f, 0, 0.125f, 0, 0, 0, 0}));

    EXPECT_TRUE(compareImages(kActual, kReference, limits(0.25, 0.046875)).passed());
    EXPECT_FALSE(compareImages(kActual, kReference, limits(0.24, {})).passed());
}

TEST(ImageCompare, APixelFailsWhenOneOfItsChannelsExceedsTheThreshold) {
    // Threshold 0.1: pixels (0,0) (0.25) and (1,0) (0.125) fail, 2 of 4. A pixel counts once.
    ImageComparison r = compareImages(kActual, kReference, limits({}, {}, 0.1, 0.25));
    EXPECT_EQ(r.metrics.failingPixels, 2);
    EXPECT_DOUBLE_EQ(r.metrics.failFraction(), 0.5);
    ASSERT_EQ(r.checks.size(), 1u);
    EXPECT_EQ(r.checks[0].kind, LimitCheck::Kind::FailFraction);
    EXPECT_FALSE(r.passed());
    EXPECT_EQ(r.describe(), "fail fraction 0.5 > 0.25 (2 of 4 pixels with error > 0.1)");
    EXPECT_TRUE(compareImages(kActual, kReference, limits({}, {}, 0.1, 0.5)).passed());
    // "Above" the threshold is strict: 0.125 does not fail at 0.125.
    ImageComparison atEdge = compareImages(kActual, kReference, limits({}, {}, 0.125, 0.0));
    EXPECT_EQ(atEdge.metrics.failingPixels, 1);
    EXPECT_FALSE(atEdge.passed());
    EXPECT_EQ(compareImages(kActual, kReference, limits({}, {}, 0.25, 0.0)).metrics.failingPixels, 0);
}

TEST(ImageCompare, FailFractionOverManyPixels) {
    // Eight pixels, one channel: errors 0, 1/32, 1/16, 1/4 and four zeros; threshold 0.05 fails
    // 2 of 8.
    Image a = image(8, 1, 1, {1, 1 + 1.0f / 32, 1 + 1.0f / 16, 1.25f, 3, 3, 3, 3});
    Image b = image(8, 1, 1, {1, 1, 1, 1, 3, 3, 3, 3});
    ImageComparison r = compareImages(a, b, limits({}, {}, 0.05, 0.2));
    EXPECT_EQ(r.metrics.failingPixels, 2);
    EXPECT_DOUBLE_EQ(r.metrics.failFraction(), 0.25);
    EXPECT_FALSE(r.passed());
    EXPECT_TRUE(compareImages(a, b, limits({}, {}, 0.05, 0.25)).passed());
    EXPECT_DOUBLE_EQ(r.metrics.maxError, 0.25);
    EXPECT_EQ(r.metrics.maxX, 3);
    EXPECT_DOUBLE_EQ(r.metrics.meanError, (1.0 / 32 + 1.0 / 16 + 0.25) / 8);
}

TEST(ImageCompare, RelativeErrorDividesByTheReferenceOrTheFloor) {
    // 2x2, one channel. floor 0.5: |2.5−2|/2 = 0.25, |0.5−0.25|/max(0.25, 0.5) = 0.5,
    // |−3+4|/4 = 0.25, |0.0625−0|/0.5 = 0.125. Max 0.5 at x=1 y=0, mean 1.125 / 4.
    Image a = image(2, 2, 1, {2.5f, 0.5f, -3.0f, 0.0625f});
    Image b = image(2, 2, 1, {2.0f, 0.25f, -4.0f, 0.0f});
    CompareLimits l = limits(0.5, {});
    l.metric = ErrorMetric::Relative;
    l.floor = 0.5;
    ImageComparison r = compareImages(a, b, l);
    EXPECT_EQ(r.difference.pixels, (std::vector<float>{0.25f, 0.5f, 0.25f, 0.125f}));
    EXPECT_DOUBLE_EQ(r.metrics.maxError, 0.5);
    EXPECT_EQ(r.metrics.maxX, 1);
    EXPECT_EQ(r.metrics.maxY, 0);
    EXPECT_DOUBLE_EQ(r.metrics.meanError, 1.125 / 4);
    EXPECT_TRUE(r.passed());
    EXPECT_EQ(r.describe(), "max relative error 0.5 ≤ 0.5 at x=1 y=0 channel 0");

    // The default floor 1e-3: 0.25/0.25 = 1 and 0.0625/0.001 = 62.5 (the floor in float).
    l.floor = 1e-3;
    ImageComparison small = compareImages(a, b, l);
    EXPECT_FLOAT_EQ(small.difference.pixels[1], 1.0f);
    EXPECT_FLOAT_EQ(small.difference.pixels[3], 0.0625f / 0.001f);
    EXPECT_FLOAT_EQ(static_cast<float>(small.metrics.maxError), 62.5f);
    EXPECT_EQ(small.metrics.maxX, 1);
    EXPECT_EQ(small.metrics.maxY, 1);
    EXPECT_FALSE(small.passed());
}

TEST(ImageCompare, SizeAndChannelMismatchesAreFailuresWithoutMetrics) {
    ImageComparison size = compareImages(image(2, 1, 1, {0, 0}), image(1, 2, 1, {0, 0}), limits(1.0, {}));
    EXPECT_EQ(size.problem, "size: the render is 2x1, the reference 1x2");
    EXPECT_FALSE(size.passed());
    EXPECT_TRUE(size.difference.empty());
    EXPECT_TRUE(size.checks.empty());
    EXPECT_EQ(size.describe(), "size: the render is 2x1, the reference 1x2");

    ImageComparison channels = compareImages(image(1, 1, 4, {0, 0, 0, 1}), image(1, 1, 3, {0, 0, 0}), limits(1.0, {}));
    EXPECT_EQ(channels.problem, "channels: the render has 4, the reference 3");
    EXPECT_FALSE(channels.passed());
}

TEST(ImageCompare, NaNInTheRenderWhereTheReferenceIsFiniteFails) {
    Image a = image(2, 1, 2, {0.5f, 0.5f, kNaN, 0.25f});
    Image b = image(2, 1, 2, {0.5f, 0.5f, 0.375f, 0.25f});
    ImageComparison r = compareImages(a, b, limits(1.0, {}));
    EXPECT_EQ(r.problem,
              "1 value is NaN or infinite in one image and not the same in the other; the first at x=1 y=0 channel 0: "
              "render nan, reference 0.375");
    EXPECT_FALSE(r.passed());
    // The other values still measure: all equal.
    EXPECT_DOUBLE_EQ(r.metrics.maxError, 0.0);
    EXPECT_EQ(r.describe(), r.problem + "; max error 0 ≤ 1");  // no place for a zero error
    // The same in the reference (a NaN where the render is finite) fails too.
    EXPECT_FALSE(compareImages(b, a, limits(1.0, {})).passed());
}

TEST(ImageCompare, NaNAndInfinityMatchTheSameInTheReference) {
    Image a = image(2, 1, 2, {kNaN, 1.0f, kInf, 0.25f});
    Image b = image(2, 1, 2, {kNaN, 1.0f, kInf, 0.125f});
    ImageComparison r = compareImages(a, b, limits(0.0, {}));
    EXPECT_EQ(r.problem, "");
    EXPECT_EQ(r.difference.pixels, (std::vector<float>{0, 0, 0, 0.125f}));
    EXPECT_DOUBLE_EQ(r.metrics.maxError, 0.125);
    EXPECT_DOUBLE_EQ(r.metrics.meanError, 0.125 / 4);
    EXPECT_FALSE(r.passed());  // max 0 allows no difference at all

    // Infinity against a finite value, or against −infinity, is a mismatch; each one counts.
    EXPECT_EQ(compareImages(image(2, 1, 1, {kInf, kInf}), image(2, 1, 1, {1e30f, -kInf}), limits(1.0, {})).problem,
              "2 values are NaN or infinite in one image and not the same in the other; the first at x=0 y=0 channel "
              "0: render inf, reference 1e+30");
}

TEST(ImageCompare, PercentileOfTheErrors) {
    // The eight channel errors of kActual against kReference, sorted: six 0, 0.125, 0.25. The
    // 90th percentile lies at rank 0.9·7 = 6.3: 0.125 + 0.3·0.125.
    CompareLimits l = limits({}, {});
    l.percentile = PercentileLimit{90, 0.15};
    ImageComparison r = compareImages(kActual, kReference, l);
    EXPECT_DOUBLE_EQ(r.metrics.percentileError, 0.1625);
    ASSERT_EQ(r.checks.size(), 1u);
    EXPECT_EQ(r.checks[0].kind, LimitCheck::Kind::Percentile);
    EXPECT_FALSE(r.passed());
    EXPECT_EQ(r.describe(), "90th percentile error 0.1625 > 0.15");
    l.percentile = PercentileLimit{100, 0.25};  // the maximum
    EXPECT_TRUE(compareImages(kActual, kReference, l).passed());
    // Checks keep the order max, mean, percentile, fail fraction; the percentile reads as an ordinal.
    l = limits(1.0, 1.0, 1.0);
    for (auto [p, words] : std::initializer_list<std::pair<double, const char*>>{
             {1, "1st"}, {2, "2nd"}, {3, "3rd"}, {11, "11th"}, {12, "12th"}, {13, "13th"}, {21, "21st"},
             {99.5, "99.5th"}, {100, "100th"}}) {
        l.percentile = PercentileLimit{p, 1.0};
        ImageComparison ordered = compareImages(kActual, kReference, l);
        ASSERT_EQ(ordered.checks.size(), 4u);
        EXPECT_EQ(ordered.checks[2].kind, LimitCheck::Kind::Percentile);
        EXPECT_NE(ordered.describe().find("; " + std::string(words) + " percentile error "), std::string::npos)
            << ordered.describe();
    }
}

// ---- ΔE_ITP ----

// ΔE_ITP of two greys given in cd/m², from the PQ inverse EOTF of SMPTE ST 2084.
double greyDeltaE(double a, double b) {
    auto pq = [](double cdm2) {
        double y = std::pow(cdm2 / 10000, 0.1593017578125);
        return std::pow((0.8359375 + 18.8515625 * y) / (1 + 18.6875 * y), 78.84375);
    };
    return 720 * std::abs(pq(a) - pq(b));
}

// As describe() prints a measured value: a float, 6 significant digits.
std::string printed(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", static_cast<double>(static_cast<float>(v)));
    return text;
}

CompareLimits itp(double luminance = 100) {
    CompareLimits l;
    l.metric = ErrorMetric::Itp;
    l.luminance = luminance;
    return l;
}

// 2x2 RGBA greys: equal but for alpha (not compared), 1.5 against 1, equal black, 10 against 11.
const Image kItpActual = image(2, 2, 4, {1, 1, 1, 1, 1.5f, 1.5f, 1.5f, 0.5f, 0, 0, 0, 1, 10, 10, 10, 1});
const Image kItpReference = image(2, 2, 4, {1, 1, 1, 0, 1, 1, 1, 1, 0, 0, 0, 1, 11, 11, 11, 1});

TEST(ImageCompare, ItpIsOneErrorAPixel) {
    // 1.0 = 100 cd/m²: 150 against 100 and 1000 against 1100 cd/m².
    const double e1 = greyDeltaE(150, 100), e3 = greyDeltaE(1000, 1100);
    CompareLimits l = itp();
    l.max = 30;
    l.mean = 9;
    l.percentile = PercentileLimit{50, 4};
    l.pixel = 10;
    ImageComparison r = compareImages(kItpActual, kItpReference, l);
    EXPECT_EQ(r.problem, "");
    ASSERT_EQ(r.difference.channels, 1);
    ASSERT_EQ(r.difference.pixels.size(), 4u);
    EXPECT_EQ(r.difference.pixels[0], 0.0f);
    EXPECT_NEAR(r.difference.pixels[1], e1, 1e-5 * e1);
    EXPECT_EQ(r.difference.pixels[2], 0.0f);
    EXPECT_NEAR(r.difference.pixels[3], e3, 1e-5 * e3);
    EXPECT_NEAR(r.metrics.maxError, e1, 1e-5 * e1);  // 29.68
    EXPECT_EQ(r.metrics.maxX, 1);
    EXPECT_EQ(r.metrics.maxY, 0);
    EXPECT_NEAR(r.metrics.meanError, (e1 + e3) / 4, 1e-5 * e1);  // 9.29
    // Sorted 0, 0, e3, e1: the median lies halfway between 0 and e3.
    EXPECT_NEAR(r.metrics.percentileError, e3 / 2, 1e-5 * e3);  // 3.74
    EXPECT_EQ(r.metrics.failingPixels, 1);
    EXPECT_EQ(r.metrics.pixelCount, 4);
    ASSERT_EQ(r.checks.size(), 4u);
    EXPECT_FALSE(r.passed());
    EXPECT_EQ(r.describe(), "max ΔE_ITP " + printed(r.metrics.maxError) + " ≤ 30 at x=1 y=0; mean ΔE_ITP " +
                                printed(r.metrics.meanError) + " > 9; 50th percentile ΔE_ITP " +
                                printed(r.metrics.percentileError) +
                                " ≤ 4; fail fraction 0.25 > 0 (1 of 4 pixels with ΔE_ITP > 10)");
    EXPECT_EQ(compareImages(kItpActual, kItpReference, itp()).describe(),
              "max ΔE_ITP " + printed(e1) + " at x=1 y=0, mean ΔE_ITP " + printed(r.metrics.meanError));
}

TEST(ImageCompare, ItpLuminanceIsWhatOneStandsFor) {
    // 1.0 = 1000 cd/m²: 1500 against 1000 and 10000 against 11000 cd/m².
    ImageComparison r = compareImages(kItpActual, kItpReference, itp(1000));
    const double e1 = greyDeltaE(1500, 1000), e3 = greyDeltaE(10000, 11000);
    EXPECT_NEAR(r.difference.pixels[1], e1, 1e-5 * e1);
    EXPECT_NEAR(r.difference.pixels[3], e3, 1e-5 * e3);
}

TEST(ImageCompare, ItpOfOneAndTwoChannelImagesIsOfGreys) {
    const double e0 = greyDeltaE(150, 100), e1 = greyDeltaE(1000, 1100);
    ImageComparison one = compareImages(image(2, 1, 1, {1.5f, 10}), image(2, 1, 1, {1, 11}), itp());
    ASSERT_EQ(one.difference.pixels.size(), 2u);
    EXPECT_NEAR(one.difference.pixels[0], e0, 1e-5 * e0);
    EXPECT_NEAR(one.difference.pixels[1], e1, 1e-5 * e1);
    // The second channel is alpha.
    ImageComparison two = compareImages(image(2, 1, 2, {1.5f, 0, 10, 1}), image(2, 1, 2, {1, 1, 11, 1}), itp());
    EXPECT_EQ(two.difference.pixels, one.difference.pixels);
    // Three channels are RGB.
    ImageComparison three = compareImages(image(1, 1, 3, {1.5f, 1.5f, 1.5f}), image(1, 1, 3, {1, 1, 1}), itp());
    EXPECT_EQ(three.difference.pixels[0], one.difference.pixels[0]);
}

TEST(ImageCompare, ItpOfAPixelWithANaNOrInfinityIsZero) {
    // Pixel 0: the same NaN in both, no error. Pixel 1: infinity against a finite value, a
    // mismatch the problem names; its error is 0 too. Pixel 2 measures.
    Image a = image(3, 1, 3, {kNaN, 1, 1, kInf, 0, 0, 1.5f, 1.5f, 1.5f});
    Image b = image(3, 1, 3, {kNaN, 1, 1, 4, 0, 0, 1, 1, 1});
    ImageComparison r = compareImages(a, b, itp());
    EXPECT_EQ(r.problem,
              "1 value is NaN or infinite in one image and not the same in the other; the first at x=1 y=0 channel 0: "
              "render inf, reference 4");
    ASSERT_EQ(r.difference.pixels.size(), 3u);
    EXPECT_EQ(r.difference.pixels[0], 0.0f);
    EXPECT_EQ(r.difference.pixels[1], 0.0f);
    EXPECT_NEAR(r.difference.pixels[2], greyDeltaE(150, 100), 1e-3);
    EXPECT_EQ(r.metrics.maxX, 2);
    EXPECT_FALSE(r.passed());
}

TEST(ImageCompare, WithoutLimitsItDescribesWhatItMeasured) {
    ImageComparison r = compareImages(kActual, kReference, CompareLimits{});
    EXPECT_TRUE(r.passed());
    EXPECT_EQ(r.describe(), "max error 0.25 at x=0 y=0 channel 1, mean error 0.046875");
}

}  // namespace
}  // namespace rmfx
