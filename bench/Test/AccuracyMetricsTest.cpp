// The bench's error metrics (bench/accuracy/AccuracyMetrics.h): PSNR of a known MSE and of equal
// images, the relative error's floor, NaN counting as infinite, and the per-stage metrics.

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "bench/accuracy/AccuracyMetrics.h"
#include "bench/accuracy/IdealLuminance.h"
#include "bench/accuracy/IdealToneMap.h"

namespace rmfx::accuracy {
namespace {

LinearImage greyRow(std::vector<double> values) {
    LinearImage image(static_cast<int>(values.size()), 1);
    for (size_t x = 0; x < values.size(); ++x)
        for (int c = 0; c < 3; ++c) image.at(static_cast<int>(x), 0, c) = values[x];
    return image;
}

TEST(AccuracyMetrics, PsnrOfAKnownMeanSquaredError) {
    LinearImage a = greyRow({10, 20, 30, 40}), b = a;
    b.at(1, 0, 1) += 6.0;  // one value of 12 off by 6: MSE = 36 / 12 = 3
    EXPECT_NEAR(psnr8(a, b), 10.0 * std::log10(255.0 * 255.0 / 3.0), 1e-12);
    EXPECT_NEAR(psnr8(a, b), 43.3596, 1e-4);
    EXPECT_EQ(psnr8(a, a), std::numeric_limits<double>::infinity());
}

TEST(AccuracyMetrics, RelativeErrorUsesAFloorOfAThousandthOfTheMeanIdealLuminance) {
    LinearImage ideal = greyRow({0.0, 2.0});  // mean Y 1: floor 1e-3
    LinearImage actual = greyRow({0.001, 2.2});
    RelativeError e = relativeLuminanceError(actual, ideal);
    EXPECT_NEAR(e.max, 1.0, 1e-12);          // 0.001 / 1e-3
    EXPECT_NEAR(e.mean, (1.0 + 0.1) / 2, 1e-12);
    RelativeError given = relativeLuminanceError(actual, ideal, 0.5);
    EXPECT_NEAR(given.max, 0.1, 1e-12);      // 0.2 / 2 beats 0.001 / 0.5
}

TEST(AccuracyMetrics, AllBlackIdealFallsBackToAFloorOf1eMinus30) {
    LinearImage ideal = greyRow({0.0, 0.0});
    EXPECT_NEAR(relativeLuminanceError(greyRow({1e-30, 0.0}), ideal).max, 1.0, 1e-12);
    EXPECT_EQ(relativeLuminanceError(ideal, ideal).max, 0.0);
}

TEST(AccuracyMetrics, NanOrInfinityInTheActualImageIsAnInfiniteError) {
    LinearImage ideal = greyRow({1.0, 1.0});
    LinearImage actual = greyRow({1.0, std::numeric_limits<double>::quiet_NaN()});
    RelativeError e = relativeLuminanceError(actual, ideal);
    EXPECT_EQ(e.max, std::numeric_limits<double>::infinity());
    EXPECT_EQ(e.mean, std::numeric_limits<double>::infinity());
}

TEST(AccuracyMetrics, ImageStageComparesThroughTheReferenceToneMapOfTheIdealsLogAverage) {
    LinearImage ideal = greyRow({0.1, 0.5, 2.0, 8.0});
    EXPECT_EQ(imageStageMetrics(ideal, ideal).psnrDb, std::numeric_limits<double>::infinity());
    LinearImage actual = ideal;
    actual.at(3, 0, 0) = actual.at(3, 0, 1) = actual.at(3, 0, 2) = 8.8;  // +10 % on one pixel
    ErrorMetrics m = imageStageMetrics(actual, ideal);
    EXPECT_NEAR(m.maxRelative, 0.1, 1e-12);
    EXPECT_NEAR(m.meanRelative, 0.025, 1e-12);
    double lavg = idealLuminance(ideal).logAverage;
    EXPECT_NEAR(m.psnrDb, psnr8(referenceToneMap(actual, lavg), referenceToneMap(ideal, lavg)), 1e-12);
    EXPECT_TRUE(std::isfinite(m.psnrDb));
}

TEST(AccuracyMetrics, LuminanceStageErrorIsThatOfTheLogAverage) {
    LinearImage input = greyRow({0.1, 0.2, 1.0, 3.0});
    double ideal = idealLuminance(input).logAverage;
    ErrorMetrics m = luminanceStageMetrics(ideal * 1.02, ideal, input);
    EXPECT_NEAR(m.maxRelative, 0.02, 1e-12);
    EXPECT_EQ(m.meanRelative, m.maxRelative);
    EXPECT_NEAR(m.psnrDb, psnr8(referenceToneMap(input, ideal * 1.02), referenceToneMap(input, ideal)), 1e-12);
    EXPECT_EQ(luminanceStageMetrics(ideal, ideal, input).psnrDb, std::numeric_limits<double>::infinity());
}

TEST(AccuracyMetrics, ToneMapStageDecodesTheOutputAndUsesAFloorOf1Over255) {
    LinearImage display = greyRow({0.0, 0.5, 1.0});
    LinearImage eight = eightBitSrgb(display);
    LinearImage output = eight;
    for (double& v : output.rgb) v /= 255.0;  // what an rgba8 target reads back as
    ErrorMetrics exact = toneMapStageMetrics(output, display);
    EXPECT_EQ(exact.psnrDb, std::numeric_limits<double>::infinity());
    // Quantisation alone: 0.5 encodes to 187.5 / 255 → 188, decoding to 0.5029.
    EXPECT_NEAR(exact.maxRelative, std::abs(srgbDecode(188.0 / 255.0) - 0.5) / 0.5, 1e-12);
    LinearImage off = output;
    off.at(0, 0, 0) = 1.0 / 255.0;  // black pixel one step up in red: floor 1/255
    ErrorMetrics m = toneMapStageMetrics(off, display);
    EXPECT_NEAR(m.maxRelative, 0.2126 * srgbDecode(1.0 / 255.0) * 255.0, 1e-12);
    EXPECT_NEAR(m.psnrDb, 10.0 * std::log10(255.0 * 255.0 / (1.0 / 9.0)), 1e-9);
}

}  // namespace
}  // namespace rmfx::accuracy
