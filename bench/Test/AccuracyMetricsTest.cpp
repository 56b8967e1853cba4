// The bench's error metrics (bench/accuracy/AccuracyMetrics.h): PSNR of a known MSE and of equal
// images, the relative error's floor, NaN counting as infinite, and the per-stage metrics.

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "bench/accuracy/AccuracyMetrics.h"
#include "reference/IdealLuminance.h"
#include "reference/IdealToneMap.h"

namespace rmfx::accuracy {
namespace {

using test::RefImage;

RefImage greyRow(std::vector<double> values) {
    RefImage image(static_cast<int>(values.size()), 1);
    for (size_t x = 0; x < values.size(); ++x)
        image.at(static_cast<int>(x), 0) = glm::dvec4(glm::dvec3(values[x]), 1.0);
    return image;
}

TEST(AccuracyMetrics, PsnrOfAKnownMeanSquaredError) {
    RefImage a = greyRow({10, 20, 30, 40}), b = a;
    b.at(1, 0)[1] += 6.0;  // one value of 12 off by 6: MSE = 36 / 12 = 3
    EXPECT_NEAR(psnr8(a, b), 10.0 * std::log10(255.0 * 255.0 / 3.0), 1e-12);
    EXPECT_NEAR(psnr8(a, b), 43.3596, 1e-4);
    EXPECT_EQ(psnr8(a, a), std::numeric_limits<double>::infinity());
}

TEST(AccuracyMetrics, RelativeErrorUsesAFloorOfAThousandthOfTheMeanIdealLuminance) {
    RefImage ideal = greyRow({0.0, 2.0});  // mean Y 1: floor 1e-3
    RefImage actual = greyRow({0.001, 2.2});
    RelativeError e = relativeLuminanceError(actual, ideal);
    EXPECT_NEAR(e.max, 1.0, 1e-12);          // 0.001 / 1e-3
    EXPECT_NEAR(e.mean, (1.0 + 0.1) / 2, 1e-12);
    RelativeError given = relativeLuminanceError(actual, ideal, 0.5);
    EXPECT_NEAR(given.max, 0.1, 1e-12);      // 0.2 / 2 beats 0.001 / 0.5
}

TEST(AccuracyMetrics, AllBlackIdealFallsBackToAFloorOf1eMinus30) {
    RefImage ideal = greyRow({0.0, 0.0});
    EXPECT_NEAR(relativeLuminanceError(greyRow({1e-30, 0.0}), ideal).max, 1.0, 1e-12);
    EXPECT_EQ(relativeLuminanceError(ideal, ideal).max, 0.0);
}

TEST(AccuracyMetrics, NanOrInfinityInTheActualImageIsAnInfiniteError) {
    RefImage ideal = greyRow({1.0, 1.0});
    RefImage actual = greyRow({1.0, std::numeric_limits<double>::quiet_NaN()});
    RelativeError e = relativeLuminanceError(actual, ideal);
    EXPECT_EQ(e.max, std::numeric_limits<double>::infinity());
    EXPECT_EQ(e.mean, std::numeric_limits<double>::infinity());
}

TEST(AccuracyMetrics, ImageStageComparesThroughTheReferenceToneMapOfTheIdealsLogAverage) {
    RefImage ideal = greyRow({0.1, 0.5, 2.0, 8.0});
    EXPECT_EQ(imageStageMetrics(ideal, ideal).psnrDb, std::numeric_limits<double>::infinity());
    RefImage actual = ideal;
    actual.at(3, 0)[0] = actual.at(3, 0)[1] = actual.at(3, 0)[2] = 8.8;  // +10 % on one pixel
    ErrorMetrics m = imageStageMetrics(actual, ideal);
    EXPECT_NEAR(m.maxRelative, 0.1, 1e-12);
    EXPECT_NEAR(m.meanRelative, 0.025, 1e-12);
    double lavg = test::idealLuminance(ideal).logAverage;
    EXPECT_NEAR(m.psnrDb, psnr8(referenceToneMap(actual, lavg), referenceToneMap(ideal, lavg)), 1e-12);
    EXPECT_TRUE(std::isfinite(m.psnrDb));
}

TEST(AccuracyMetrics, LuminanceStageErrorIsThatOfTheLogAverage) {
    RefImage input = greyRow({0.1, 0.2, 1.0, 3.0});
    double ideal = test::idealLuminance(input).logAverage;
    ErrorMetrics m = luminanceStageMetrics(ideal * 1.02, ideal, input);
    EXPECT_NEAR(m.maxRelative, 0.02, 1e-12);
    EXPECT_EQ(m.meanRelative, m.maxRelative);
    EXPECT_NEAR(m.psnrDb, psnr8(referenceToneMap(input, ideal * 1.02), referenceToneMap(input, ideal)), 1e-12);
    EXPECT_EQ(luminanceStageMetrics(ideal, ideal, input).psnrDb, std::numeric_limits<double>::infinity());
}

TEST(AccuracyMetrics, ToneMapStageDecodesTheOutputAndUsesAFloorOf1Over255) {
    RefImage display = greyRow({0.0, 0.5, 1.0});
    RefImage eight = test::eightBitSrgb(display);
    RefImage output = eight;
    // What an rgba8 target reads back as.
    for (glm::dvec4& t : output.texels) t = glm::dvec4(glm::dvec3(t) / 255.0, 1.0);
    ErrorMetrics exact = toneMapStageMetrics(output, display);
    EXPECT_EQ(exact.psnrDb, std::numeric_limits<double>::infinity());
    // Quantisation alone: 0.5 encodes to 187.5 / 255 → 188, decoding to 0.5029.
    EXPECT_NEAR(exact.maxRelative, std::abs(test::srgbDecode(188.0 / 255.0) - 0.5) / 0.5, 1e-12);
    RefImage off = output;
    off.at(0, 0)[0] = 1.0 / 255.0;  // black pixel one step up in red: floor 1/255
    ErrorMetrics m = toneMapStageMetrics(off, display);
    EXPECT_NEAR(m.maxRelative, 0.2126 * test::srgbDecode(1.0 / 255.0) * 255.0, 1e-12);
    EXPECT_NEAR(m.psnrDb, 10.0 * std::log10(255.0 * 255.0 / (1.0 / 9.0)), 1e-9);
}

}  // namespace
}  // namespace rmfx::accuracy
