// The building blocks of the CPU references: half and 8-bit rounding, GL-style sampling.

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "reference/CpuImage.h"

namespace rmfx::test {
namespace {

TEST(CpuImage, RoundToHalfMatchesIeeeBinary16) {
    EXPECT_EQ(roundToHalf(1.0), 1.0);
    EXPECT_EQ(roundToHalf(1.0 + 1.0 / 2048.0), 1.0);                 // tie, to even
    EXPECT_EQ(roundToHalf(1.0 + 3.0 / 2048.0), 1.0 + 2.0 / 1024.0);  // tie, to even (up)
    EXPECT_EQ(roundToHalf(0.1), 0.0999755859375);
    EXPECT_EQ(roundToHalf(65504.0), 65504.0);
    EXPECT_EQ(roundToHalf(65519.0), 65504.0);
    EXPECT_TRUE(std::isinf(roundToHalf(65520.0)));
    EXPECT_EQ(roundToHalf(std::ldexp(1.0, -24)), std::ldexp(1.0, -24));  // smallest subnormal
    EXPECT_EQ(roundToHalf(std::ldexp(1.0, -26)), 0.0);
    EXPECT_EQ(roundToHalf(-2.5), -2.5);
}

TEST(CpuImage, RoundToUnorm8ClampsAndRounds) {
    EXPECT_EQ(roundToUnorm8(-1.0), 0.0);
    EXPECT_EQ(roundToUnorm8(2.0), 1.0);
    EXPECT_EQ(roundToUnorm8(0.5), 128.0 / 255.0);  // 127.5 ties to even: 128
    EXPECT_EQ(roundToUnorm8(std::numeric_limits<double>::quiet_NaN()), 0.0);
}

TEST(CpuImage, BilinearSamplingFollowsTexelCentresAndClampsAtEdges) {
    RefImage image(2, 1);
    image.at(0, 0) = glm::dvec4(0.0);
    image.at(1, 0) = glm::dvec4(1.0);
    EXPECT_DOUBLE_EQ(sampleBilinear(image, {0.25, 0.5}).x, 0.0);  // centre of texel 0
    EXPECT_DOUBLE_EQ(sampleBilinear(image, {0.5, 0.5}).x, 0.5);
    EXPECT_DOUBLE_EQ(sampleBilinear(image, {0.625, 0.5}).x, 0.75);
    EXPECT_DOUBLE_EQ(sampleBilinear(image, {1.5, 0.5}).x, 1.0);  // clamped
    EXPECT_DOUBLE_EQ(sampleNearest(image, {0.49, 0.5}).x, 0.0);
    EXPECT_DOUBLE_EQ(sampleNearest(image, {0.51, 0.5}).x, 1.0);
}

TEST(CpuImage, FromImagePutsRowZeroAtTheBottom) {
    Image image;
    image.width = 1;
    image.height = 2;
    image.channels = 1;
    image.pixels = {0.25f, 0.75f};  // top, bottom
    RefImage ref = fromImage(image);
    EXPECT_EQ(ref.at(0, 0), glm::dvec4(0.75, 0.75, 0.75, 1.0));
    EXPECT_EQ(ref.at(0, 1), glm::dvec4(0.25, 0.25, 0.25, 1.0));
}

}  // namespace
}  // namespace rmfx::test
