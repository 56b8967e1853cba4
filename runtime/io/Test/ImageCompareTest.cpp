// compareImages against metrics computed by hand. The values are binary fractions, so every
// error below is exact in float.

#include "io/image/ImageCompare.h"

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

TEST(ImageCompare, WithoutLimitsItDescribesWhatItMeasured) {
    ImageComparison r = compareImages(kActual, kReference, CompareLimits{});
    EXPECT_TRUE(r.passed());
    EXPECT_EQ(r.describe(), "max error 0.25 at x=0 y=0 channel 1, mean error 0.046875");
}

}  // namespace
}  // namespace rmfx
