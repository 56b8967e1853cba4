// bench/PairedFrames.h: pairs alternate which executor renders first, and each measure of a frame
// gives its own ratios.

#include <array>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "bench/PairedFrames.h"

namespace rmfx::bench {
namespace {

TEST(PairedFrames, EachPairAlternatesWhichExecutorRendersFirstAndEachMeasureHasItsRatios) {
    std::vector<std::pair<int, int>> calls;  // (executor, pair) in call order
    // Executor A's frames take 3 ms of wall clock and 5 of CPU, B's 2 and 4; pair 1 runs slower.
    const auto ratios = pairedRatiosOf<2>(4, [&](int executor, int pair) {
        calls.emplace_back(executor, pair);
        const double slow = pair == 1 ? 10.0 : 1.0;
        return executor == 0 ? std::array<double, 2>{3.0 * slow, 5.0} : std::array<double, 2>{2.0 * slow, 4.0};
    });
    const std::vector<std::pair<int, int>> expected = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 2}, {1, 2}, {1, 3}, {0, 3}};
    EXPECT_EQ(calls, expected);
    EXPECT_EQ(ratios[0], std::vector<double>(4, 1.5));   // a pair's slowdown falls on both its frames
    EXPECT_EQ(ratios[1], std::vector<double>(4, 1.25));
}

TEST(PairedFrames, AFrameOfBMeasuredAsZeroGivesNoRatio) {
    const auto ratios = pairedRatiosOf<2>(3, [](int executor, int pair) {
        return std::array<double, 2>{executor == 0 ? 2.0 : 1.0, executor == 1 && pair == 1 ? 0.0 : 1.0};
    });
    EXPECT_EQ(ratios[0].size(), 3u);
    EXPECT_EQ(ratios[1].size(), 2u);
    EXPECT_EQ(pairedRatios(2, [](int executor, int) { return executor == 0 ? 6.0 : 3.0; }), std::vector<double>(2, 2.0));
}

}  // namespace
}  // namespace rmfx::bench
