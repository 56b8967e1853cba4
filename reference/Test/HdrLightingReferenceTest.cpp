// The float64 references of effects/hdr_lighting.xml checked against the sample's definitions
// directly (no GL): kernels normalised and symmetric, the blue-shift ramp, the closed form of the
// adaptation, the star table.

#include <cmath>

#include <gtest/gtest.h>

#include "reference/HdrLightingReference.h"

namespace rmfx::test {
namespace {

TEST(HdrLightingReference, NormalisedSymmetricGaussians) {
    std::vector<double> bloom = hdr::bloomKernel();
    ASSERT_EQ(bloom.size(), 15u);
    double sum = 0.0;
    for (size_t i = 0; i < bloom.size(); ++i) {
        sum += bloom[i];
        EXPECT_EQ(bloom[i], bloom[bloom.size() - 1 - i]);
    }
    EXPECT_NEAR(sum, 1.0, 1e-15);
    EXPECT_GT(bloom[7], bloom[6]);
    // σ = 3: the centre is exp(0) and the ends exp(-49/18) of it before normalising.
    EXPECT_NEAR(bloom[0] / bloom[7], std::exp(-49.0 / 18.0), 1e-15);
    double sum5 = 0.0;
    std::vector<hdr::Tap> taps = hdr::gauss5x5Kernel();
    EXPECT_EQ(taps.size(), 13u);
    for (const hdr::Tap& t : taps) sum5 += t.weight;
    EXPECT_NEAR(sum5, 1.0, 1e-15);
}

TEST(HdrLightingReference, BlueShiftCoefficient) {
    EXPECT_DOUBLE_EQ(hdr::blueShiftCoefficient(0.0), 1.0 - 1.5 / 4.1);
    EXPECT_DOUBLE_EQ(hdr::blueShiftCoefficient(2.6), 0.0);
    EXPECT_DOUBLE_EQ(hdr::blueShiftCoefficient(10.0), 0.0);
    EXPECT_DOUBLE_EQ(hdr::blueShiftCoefficient(-1.5), 1.0);
    EXPECT_DOUBLE_EQ(hdr::blueShiftCoefficient(0.55), 0.5);
}

TEST(HdrLightingReference, AdaptationStepsComposeToTheClosedForm) {
    double a = 1.0;
    for (int i = 0; i < 240; ++i) a = hdr::adaptationStep(a, 0.05, 1.0 / 120.0);
    EXPECT_NEAR(a, hdr::adaptedAfter(1.0, 0.05, 2.0), 1e-14);
    EXPECT_NEAR(hdr::adaptedAfter(1.0, 0.05, 2.0), 0.05 + 0.95 * std::pow(0.98, 60.0), 1e-15);
}

TEST(HdrLightingReference, StarTypes) {
    const size_t lines[5] = {4, 4, 6, 2, 8};
    for (int type = 0; type < 5; ++type) EXPECT_EQ(hdr::starLines(type).size(), lines[type]);
    EXPECT_NEAR(hdr::starLines(2)[1].angleRadians, (20.0 + 60.0) * std::acos(-1.0) / 180.0, 1e-15);
    EXPECT_EQ(hdr::starLines(4)[0].attenuation, 0.95);
    EXPECT_EQ(hdr::starLines(4)[1].attenuation, 0.88);
    // The last pass is white (0.63), whatever the chromatic aberration; the first is coloured.
    EXPECT_EQ(hdr::starColor(2, 2, 1.0), glm::dvec3(0.63));
    EXPECT_NEAR(hdr::starColor(0, 2, 1.0).r, 1.0 + (0.63 - 1.0) / 3.0, 1e-15);
    EXPECT_EQ(hdr::starColor(0, 2, 0.0), glm::dvec3(0.63));
}

}  // namespace
}  // namespace rmfx::test
