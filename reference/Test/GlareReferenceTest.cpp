// Self-checks of the glare reference (tests/reference/GlareReference.h) that need no GL: the
// kernels' weights and variances, the identity behind exercise 1 (one 7x7 binomial pass = three
// 3x3 passes), clamp addressing at the borders and the 8-bit alpha x64 quantisation.

#include <cmath>

#include <gtest/gtest.h>

#include "reference/GlareReference.h"

namespace rmfx::test {
namespace {

double weightSum(const std::vector<KernelTap>& kernel) {
    double sum = 0.0;
    for (const KernelTap& t : kernel) sum += t.weight;
    return sum;
}

TEST(GlareReferenceTest, KernelsAreNormalisedBinomials) {
    EXPECT_EQ(gauss9Kernel().size(), 9u);
    EXPECT_EQ(gauss49Kernel().size(), 49u);
    EXPECT_DOUBLE_EQ(weightSum(gauss9Kernel()), 1.0);
    EXPECT_DOUBLE_EQ(weightSum(gauss49Kernel()), 1.0);
    EXPECT_DOUBLE_EQ(kernelVariance(gauss9Kernel()).x, 0.5);
    EXPECT_DOUBLE_EQ(kernelVariance(gauss9Kernel()).y, 0.5);
    EXPECT_DOUBLE_EQ(kernelVariance(gauss49Kernel()).x, 1.5);
    EXPECT_DOUBLE_EQ(kernelVariance(gauss49Kernel()).y, 1.5);
    // The four corners are the four diagonals (the chapter's table repeats (-1, 1)).
    int corners = 0;
    for (const KernelTap& t : gauss9Kernel())
        if (std::abs(t.offset.x) == 1 && std::abs(t.offset.y) == 1) ++corners;
    EXPECT_EQ(corners, 4);
}

TEST(GlareReferenceTest, OneGauss49PassIsThreeGauss9Passes) {
    RefImage impulse(21, 21);
    impulse.at(10, 10) = glm::dvec4(1.0);
    RefImage nine = impulse;
    for (int i = 0; i < 3; ++i) nine = blurPass(nine, 21, 21, gauss9Kernel());
    RefImage fortyNine = blurPass(impulse, 21, 21, gauss49Kernel());
    EXPECT_LT(maxAbsDifference(nine, fortyNine), 1e-15);
    EXPECT_NEAR(imageMoments(fortyNine, 0).variance.x, 1.5, 1e-12);
    EXPECT_NEAR(imageMoments(fortyNine, 0).total, 1.0, 1e-12);
}

TEST(GlareReferenceTest, BlurPassClampsAtTheBorders) {
    // A constant image stays constant: taps outside read the edge texels.
    RefImage flat(8, 8, glm::dvec4(0.25, 0.5, 1.0, 1.0));
    EXPECT_LT(maxAbsDifference(blurPass(flat, 8, 8, gauss49Kernel()), flat), 1e-15);
    // A corner impulse: the clamped taps all land on it, (1 + 6 + 15 + 20) / 64 per axis.
    RefImage corner(8, 8);
    corner.at(0, 0) = glm::dvec4(1.0);
    double axis = 42.0 / 64.0;
    EXPECT_NEAR(blurPass(corner, 8, 8, gauss49Kernel()).at(0, 0).r, axis * axis, 1e-15);
}

TEST(GlareReferenceTest, Alpha64EncodingQuantisesTheMultiplierTo64Over255) {
    glm::dvec3 rgb(0.8, 0.4, 0.2);
    for (double multiplier : {0.5, 1.0, 7.3, 32.5, 63.9}) {
        glm::dvec4 encoded = encodeAlpha64(rgb, multiplier);
        EXPECT_DOUBLE_EQ(decodeAlpha64(encoded).r, rgb.r * multiplier);
        glm::dvec4 stored(roundToUnorm8(encoded.r), roundToUnorm8(encoded.g), roundToUnorm8(encoded.b),
                          roundToUnorm8(encoded.a));
        EXPECT_LE(std::abs(stored.a * 64.0 - multiplier), 32.0 / 255.0 + 1e-12) << multiplier;
        EXPECT_LE(std::abs(decodeAlpha64(stored).r - rgb.r * multiplier),
                  0.5 / 255.0 * multiplier + rgb.r * 32.0 / 255.0 + 16.0 / 255.0 / 255.0 + 1e-12);
    }
    // Above 64 the alpha clips.
    EXPECT_DOUBLE_EQ(roundToUnorm8(encodeAlpha64(rgb, 100.0).a) * 64.0, 64.0);
}

}  // namespace
}  // namespace rmfx::test
