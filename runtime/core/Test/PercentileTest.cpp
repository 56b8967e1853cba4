#include "core/Percentile.h"

#include <gtest/gtest.h>

namespace rmfx {

namespace {

// Hand-worked: sorted {1, 2, 4, 8, 16}, n − 1 = 4.
const std::vector<double> five{8, 1, 16, 4, 2};

TEST(Percentile, EndsAreTheMinimumAndMaximum) {
    EXPECT_EQ(percentile(five, 0.0), 1.0);
    EXPECT_EQ(percentile(five, 1.0), 16.0);
}

TEST(Percentile, ExactRanksNeedNoInterpolation) {
    EXPECT_EQ(percentile(five, 0.5), 4.0);   // h = 2
    EXPECT_EQ(percentile(five, 0.25), 2.0);  // h = 1
    EXPECT_EQ(percentile(five, 0.75), 8.0);  // h = 3
}

TEST(Percentile, BetweenRanksInterpolatesLinearly) {
    EXPECT_DOUBLE_EQ(percentile(five, 0.1), 1.4);   // h = 0.4: 1 + 0.4·(2 − 1)
    EXPECT_DOUBLE_EQ(percentile(five, 0.9), 12.8);  // h = 3.6: 8 + 0.6·(16 − 8)
    EXPECT_DOUBLE_EQ(percentile(five, 0.625), 6.0); // h = 2.5: halfway between 4 and 8
}

TEST(Percentile, MedianOfAnEvenCountIsTheMeanOfTheMiddleTwo) {
    EXPECT_DOUBLE_EQ(percentile({3, 1, 10, 7}, 0.5), 5.0);  // (3 + 7) / 2
}

TEST(Percentile, OneSampleIsEveryPercentile) {
    for (double p : {0.0, 0.3, 1.0}) EXPECT_EQ(percentile({2.5}, p), 2.5);
}

TEST(Percentile, OutOfRangeProportionsClampToTheEnds) {
    EXPECT_EQ(percentile(five, -0.5), 1.0);
    EXPECT_EQ(percentile(five, 1.5), 16.0);
}

TEST(Percentile, SortedInputNeedsNoCopy) {
    const double sorted[] = {0.0, 10.0};
    EXPECT_DOUBLE_EQ(percentileOfSorted(sorted, 0.3), 3.0);
}

}  // namespace

}  // namespace rmfx
