// The replay report's heat map: a pixel's largest error over its channels against the full scale,
// magma from black (0) to pale yellow (the scale), and cyan beyond the scale or for NaN.

#include <array>
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "io/image/ErrorHeatMap.h"

namespace rmfx {
namespace {

std::array<int, 3> colourAt(const Image& heat, int x) {
    return {static_cast<int>(std::lround(heat.at(x, 0, 0) * 255)), static_cast<int>(std::lround(heat.at(x, 0, 1) * 255)),
            static_cast<int>(std::lround(heat.at(x, 0, 2) * 255))};
}

TEST(ErrorHeatMap, TheLargestChannelErrorPicksTheColourAndBeyondTheScaleIsCyan) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    Image difference;
    difference.width = 7;
    difference.height = 1;
    difference.channels = 2;
    // Scale 0.02: 0, the scale, half of it (in the second channel), an eighth (negative), a
    // little beyond, NaN, and the midpoint between the first two stops (1/16 of the scale).
    difference.pixels = {0, 0, 0.02f, 0.001f, 0.0f, 0.01f, -0.0025f, 0, 0.0201f, 0, nan, 0, 0.00125f, 0};
    Image heat = errorHeatMap(difference, 0.02);
    ASSERT_EQ(heat.width, 7);
    ASSERT_EQ(heat.channels, 3);
    EXPECT_EQ(colourAt(heat, 0), (std::array<int, 3>{0, 0, 4}));
    EXPECT_EQ(colourAt(heat, 1), (std::array<int, 3>{252, 253, 191}));
    EXPECT_EQ(colourAt(heat, 2), (std::array<int, 3>{181, 54, 122}));
    EXPECT_EQ(colourAt(heat, 3), (std::array<int, 3>{28, 16, 68}));
    EXPECT_EQ(colourAt(heat, 4), (std::array<int, 3>{0, 229, 255}));
    EXPECT_EQ(colourAt(heat, 5), (std::array<int, 3>{0, 229, 255}));
    EXPECT_EQ(colourAt(heat, 6), (std::array<int, 3>{14, 8, 36}));
}

}  // namespace
}  // namespace rmfx
