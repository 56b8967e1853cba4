#include "core/MedianInterval.h"

#include <gtest/gtest.h>

namespace rmfx {
namespace {

std::vector<double> oneTo(int n) {  // shuffled: the function sorts
    std::vector<double> v;
    for (int i = n; i >= 1; --i) v.push_back(i);
    return v;
}

TEST(MedianInterval, BinomialTailsMatchHandCounts) {
    EXPECT_DOUBLE_EQ(binomialHalfAtMost(10, -1), 0.0);
    EXPECT_DOUBLE_EQ(binomialHalfAtMost(10, 0), 1.0 / 1024);
    EXPECT_NEAR(binomialHalfAtMost(10, 1), 11.0 / 1024, 1e-14);  // lgamma rounds in the last bits
    EXPECT_NEAR(binomialHalfAtMost(10, 5), 638.0 / 1024, 1e-14);  // 1 + 10 + 45 + 120 + 210 + 252
    EXPECT_DOUBLE_EQ(binomialHalfAtMost(10, 10), 1.0);
    EXPECT_NEAR(binomialHalfAtMost(20, 5), 21700.0 / 1048576, 1e-15);  // 1 + 20 + 190 + 1140 + 4845 + 15504
    // Past 1074 samples 2^-n underflows a double; the sum must not.
    EXPECT_NEAR(binomialHalfAtMost(2000, 999), 0.5 - 0.5 * 0.017839, 1e-5);  // C(2000, 1000)/2^2000 ≈ 0.017839
}

// Published tables of the distribution-free interval (e.g. Conover, Practical Nonparametric
// Statistics): 95 % for n = 10 is the 2nd to 9th, for n = 20 the 6th to 15th smallest.
TEST(MedianInterval, RanksAreTheTabulatedOnes) {
    MedianInterval ten = medianInterval(oneTo(10));
    EXPECT_EQ(ten.low, 2.0);
    EXPECT_EQ(ten.high, 9.0);
    EXPECT_NEAR(ten.coverage, 1.0 - 2.0 * 11.0 / 1024, 1e-14);
    EXPECT_EQ(ten.median, 5.5);
    MedianInterval twenty = medianInterval(oneTo(20));
    EXPECT_EQ(twenty.low, 6.0);
    EXPECT_EQ(twenty.high, 15.0);
    EXPECT_NEAR(twenty.coverage, 1.0 - 2.0 * 21700.0 / 1048576, 1e-12);
    EXPECT_GE(twenty.coverage, 0.95);
    // Not the 7th to 14th at 90 %: 2·P(≤ 6) = 0.1153 > 0.10.
    MedianInterval ninety = medianInterval(oneTo(20), 0.90);
    EXPECT_EQ(ninety.low, 6.0);
    EXPECT_EQ(ninety.high, 15.0);
}

TEST(MedianInterval, TooFewSamplesGiveTheRangeAndSaySo) {
    MedianInterval five = medianInterval({3.0, 1.0, 2.0, 5.0, 4.0});
    EXPECT_EQ(five.low, 1.0);
    EXPECT_EQ(five.high, 5.0);
    EXPECT_NEAR(five.coverage, 1.0 - 2.0 / 32, 1e-14);  // below the 0.95 asked for
    MedianInterval one = medianInterval({7.0});
    EXPECT_EQ(one.low, 7.0);
    EXPECT_EQ(one.high, 7.0);
    EXPECT_EQ(one.median, 7.0);
    EXPECT_DOUBLE_EQ(one.coverage, 0.0);
}

TEST(MedianInterval, TheIntervalNarrowsAsSamplesGrow) {
    MedianInterval small = medianInterval(oneTo(40)), large = medianInterval(oneTo(400));
    // Relative to the range, the interval of 400 samples is about a third as wide as of 40.
    const double smallWidth = (small.high - small.low) / 40.0, largeWidth = (large.high - large.low) / 400.0;
    EXPECT_LT(largeWidth, smallWidth * 0.45);
    EXPECT_GE(large.coverage, 0.95);
    EXPECT_LE(large.low, large.median);
    EXPECT_GE(large.high, large.median);
}

}  // namespace
}  // namespace rmfx
