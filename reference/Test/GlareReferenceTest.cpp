// Self-checks of the glare reference (tests/reference/GlareReference.h) that need no GL: the
// kernels' weights and variances, the identity behind exercise 1 (one 7x7 binomial pass = three
// 3x3 passes), clamp addressing at the borders and the 8-bit alpha x64 quantisation.

#include <cmath>
#include <cstdio>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
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

// A GPU's bilinear filter with 8 bits of subtexel precision: each fraction rounded to a 1/256 step,
// at most 2^-9 from the exact one.
glm::dvec4 sampleBilinearEightBitWeights(const RefImage& image, glm::dvec2 uv) {
    const BilinearFootprint f = bilinearFootprint(image, uv);
    const double fx = std::round(f.fx * 256.0) / 256.0, fy = std::round(f.fy * 256.0) / 256.0;
    return glm::mix(glm::mix(f.texels[0], f.texels[1], fx), glm::mix(f.texels[2], f.texels[3], fx), fy);
}

// blurChainFilteringBounds holds, texel by texel, what such a filter does to a chain of blurs of a
// high-contrast scene at a size whose taps fall between texels at every fraction (97x61 into
// 25x16), and it is not loose by orders of magnitude: in the first level some texel comes within a
// quarter of its bound, in later ones (where the errors of taps partly cancel) within a twentieth.
TEST(GlareReferenceTest, FilteringBoundsHoldForEightBitSubtexelWeights) {
    RefImage scene = shadePixels(97, 61, [](glm::dvec2 uv) {
        const double d = glm::length((uv - glm::dvec2(0.37, 0.61)) * glm::dvec2(97.0, 61.0));
        const double sun = d < 4.0 ? 16.0 : 0.05 + 0.02 * std::sin(uv.x * 40.0);
        return glm::dvec4(sun, 0.5 * sun, 0.1 + uv.y, 1.0);
    });
    const glm::ivec2 size(25, 16);
    const glm::dvec2 texel(1.0 / size.x, 1.0 / size.y);
    for (const auto& kernel : {gauss9Kernel(), gauss49Kernel()}) {
        std::vector<RefImage> exact, gpu;
        for (int k = 0; k < 4; ++k) {
            exact.push_back(blurPass(k == 0 ? scene : exact.back(), size.x, size.y, kernel));
            const RefImage& source = k == 0 ? scene : gpu.back();
            gpu.push_back(shadePixels(size.x, size.y, [&](glm::dvec2 uv) {
                glm::dvec4 sum(0.0);
                for (const KernelTap& t : kernel) sum += t.weight * sampleBilinearEightBitWeights(source, uv + t.offset * texel);
                return sum;
            }));
        }
        const std::vector<RefImage> bounds = blurChainFilteringBounds(scene, exact, size, kernel, std::ldexp(1.0, -9));
        ASSERT_EQ(bounds.size(), 4u);
        for (int k = 0; k < 4; ++k) {
            const double worst = maxDifferenceOverBound(gpu[static_cast<size_t>(k)], exact[static_cast<size_t>(k)], 1e-12, 1.0,
                                                        bounds[static_cast<size_t>(k)], 3);
            EXPECT_LE(worst, 1.0) << "level " << k + 1;
            EXPECT_GT(worst, k == 0 ? 0.25 : 0.05) << "level " << k + 1;
            std::printf("  level %d: the emulated filter's largest error is %.3f of its bound\n", k + 1, worst);
        }
        // The composite of levels 2, 3 and 4 read at 97x61.
        const RefImage combined = glareCombine(exact[1], exact[2], exact[3], glm::dvec3(0.1), 97, 61, false);
        const RefImage combinedGpu = shadePixels(97, 61, [&](glm::dvec2 uv) {
            glm::dvec3 rgb(0.0);
            for (int j = 1; j < 4; ++j) rgb += 0.1 * glm::dvec3(sampleBilinearEightBitWeights(gpu[static_cast<size_t>(j)], uv));
            return glm::dvec4(rgb, 1.0);
        });
        const RefImage combinedBound = glareCombineFilteringBound(exact[1], exact[2], exact[3], bounds[1], bounds[2], bounds[3],
                                                                  glm::dvec3(0.1), 97, 61, std::ldexp(1.0, -9));
        const double worst = maxDifferenceOverBound(combinedGpu, combined, 1e-12, 1.0, combinedBound, 3);
        EXPECT_LE(worst, 1.0);
        EXPECT_GT(worst, 0.05);
        std::printf("  composite: %.3f of its bound\n", worst);
    }
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
