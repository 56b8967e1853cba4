// The replay report's RGBE packing: every value the page decodes lies within half a mantissa step
// of the original (a step is at most 2^-7 of the pixel's largest channel), across the range from
// 1e-30 to 1e38; zero
// stays zero; what cannot be shown (negative, NaN, infinite) is black, and beyond 1.7e38 clamps.

#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "io/image/RgbePacking.h"

namespace rmfx {
namespace {

Image rgbImage(const std::vector<std::array<float, 3>>& pixels) {
    Image image;
    image.width = static_cast<int>(pixels.size());
    image.height = 1;
    image.channels = 3;
    for (const auto& p : pixels) image.pixels.insert(image.pixels.end(), p.begin(), p.end());
    return image;
}

// The byte a packed value holds, as a PNG writer rounds it.
int byteAt(const Image& packed, int x, int y, int c) { return static_cast<int>(std::lround(packed.at(x, y, c) * 255.0)); }

TEST(RgbePacking, DecodedValuesLieWithinHalfAMantissaStep) {
    std::vector<std::array<float, 3>> pixels;
    for (double v : {1e-30, 3.7e-9, 0.001, 0.18, 0.5, 1.0, 1.0 - 1e-7, 2.5, 1000.0, 65504.0, 1e20, 1e38})
        pixels.push_back({static_cast<float>(v), static_cast<float>(v * 0.37), static_cast<float>(v * 0.004)});
    Image image = rgbImage(pixels);
    Image packed = packRgbe(image);
    ASSERT_EQ(packed.width, image.width);
    ASSERT_EQ(packed.height, 2);
    ASSERT_EQ(packed.channels, 3);
    for (int x = 0; x < image.width; ++x) {
        double largest = image.at(x, 0, 0);
        int exponent = byteAt(packed, x, 1, 0);
        EXPECT_EQ(byteAt(packed, x, 1, 1), exponent);
        EXPECT_EQ(byteAt(packed, x, 1, 2), exponent);
        for (int c = 0; c < 3; ++c) {
            double decoded = unpackRgbe(byteAt(packed, x, 0, c), exponent);
            // Half a step above floor(v / step); a channel that floors to 0 shows as 0, within a step.
            const double step = std::ldexp(1.0, exponent - 136);
            EXPECT_LE(std::abs(decoded - image.at(x, 0, c)), decoded == 0.0 ? step : step / 2)
                << "pixel " << x << " channel " << c;
        }
        // The largest channel's mantissa is normalised: 128 to 255.
        EXPECT_GE(byteAt(packed, x, 0, 0), 128) << x;
        EXPECT_LE(std::abs(unpackRgbe(byteAt(packed, x, 0, 0), exponent) / largest - 1.0), 1.0 / 256) << x;
    }
}

TEST(RgbePacking, ZeroNegativeNanAndInfinityAreBlack) {
    const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
    Image packed = packRgbe(rgbImage({{0, 0, 0}, {-1, -2, -3}, {nan, nan, nan}, {inf, -inf, 0}, {-5, 2, nan}}));
    for (int x = 0; x < 4; ++x) {
        EXPECT_EQ(byteAt(packed, x, 1, 0), 0) << x;
        for (int c = 0; c < 3; ++c) EXPECT_EQ(unpackRgbe(byteAt(packed, x, 0, c), byteAt(packed, x, 1, 0)), 0.0) << x;
    }
    // Only the valid channel of a mixed pixel remains.
    int e = byteAt(packed, 4, 1, 0);
    EXPECT_EQ(unpackRgbe(byteAt(packed, 4, 0, 0), e), 0.0);
    EXPECT_NEAR(unpackRgbe(byteAt(packed, 4, 0, 1), e), 2.0, 2.0 / 256);
    EXPECT_EQ(byteAt(packed, 4, 0, 2), 0);
}

TEST(RgbePacking, ValuesBeyondTheLargestClampToIt) {
    Image packed = packRgbe(rgbImage({{3e38f, 1.0f, 0.0f}}));
    const double largest = 255.5 * std::ldexp(1.0, 119);
    EXPECT_EQ(byteAt(packed, 0, 1, 0), 255);
    EXPECT_EQ(unpackRgbe(byteAt(packed, 0, 0, 0), 255), largest);
    EXPECT_EQ(unpackRgbe(byteAt(packed, 0, 0, 2), 255), 0.0);
}

TEST(RgbePacking, OneChannelImagesAreGrey) {
    Image grey;
    grey.width = 2;
    grey.height = 1;
    grey.channels = 1;
    grey.pixels = {0.25f, 8.0f};
    Image packed = packRgbe(grey);
    for (int x = 0; x < 2; ++x)
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(unpackRgbe(byteAt(packed, x, 0, c), byteAt(packed, x, 1, c)), grey.pixels[x], grey.pixels[x] / 256);
}

}  // namespace
}  // namespace rmfx
