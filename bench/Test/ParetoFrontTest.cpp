// The Pareto front of (time, error) (bench/accuracy/ParetoFront.h), hand cases with ties, and
// the per-group marking and the spread of frame times the bench reports.

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "bench/accuracy/BenchResults.h"
#include "bench/accuracy/ParetoFront.h"
#include "bench/accuracy/TimeSummary.h"

namespace rmfx::accuracy {
namespace {

TEST(ParetoFront, KeepsWhatNothingIsBothFasterAndMoreAccurateThan) {
    std::vector<TimeError> points = {
        {1.0, 0.5},   // front: fastest but one
        {2.0, 0.1},   // front
        {2.0, 0.1},   // an equal point: neither dominates the other, both on the front
        {3.0, 0.1},   // as accurate as {2, 0.1} but slower: dominated
        {1.0, 0.6},   // as fast as {1, 0.5} but less accurate: dominated
        {0.5, 1.0},   // front: the fastest
        {4.0, 0.01},  // front: the most accurate
        {5.0, 0.2},   // dominated by several
    };
    EXPECT_EQ(paretoFront(points), (std::vector<bool>{true, true, true, false, false, true, true, false}));
}

TEST(ParetoFront, NanIsNeverOnTheFrontAndDominatesNothing) {
    double nan = std::numeric_limits<double>::quiet_NaN();
    std::vector<TimeError> points = {{1.0, nan}, {2.0, 0.5}, {nan, 0.0}};
    EXPECT_EQ(paretoFront(points), (std::vector<bool>{false, true, false}));
    // An infinite error is an ordinary (worst) value.
    EXPECT_EQ(paretoFront({{1.0, INFINITY}, {2.0, 0.5}}), (std::vector<bool>{true, true}));
    EXPECT_EQ(paretoFront({{3.0, INFINITY}, {2.0, 0.5}}), (std::vector<bool>{false, true}));
}

TEST(ParetoFront, MarkedPerInputAndStageAndOnTheSummaryOverInputs) {
    BenchResults r;
    auto row = [](std::string input, std::string stage, std::string variant, double ms, double error) {
        BenchRow b;
        b.input = input, b.stage = stage, b.variant = variant;
        b.time.median = b.time.p10 = b.time.p90 = ms;
        b.time.frames = 3;
        b.error = {error * 2, error, 40.0};
        return b;
    };
    r.rows = {row("a", "bloom", "fast", 1.0, 0.3), row("a", "bloom", "slow", 2.0, 0.1),
              row("b", "bloom", "fast", 1.0, 0.05), row("b", "bloom", "slow", 2.0, 0.1),
              row("a", "streak", "only", 9.0, 9.0)};
    addSummaryRows(r);
    markParetoFronts(r);
    ASSERT_EQ(r.rows.size(), 8u);
    EXPECT_TRUE(r.rows[0].pareto && r.rows[1].pareto);   // a: a trade-off
    EXPECT_TRUE(r.rows[2].pareto && !r.rows[3].pareto);  // b: fast is also more accurate
    EXPECT_TRUE(r.rows[4].pareto);                       // alone in its group
    const BenchRow& fastAll = r.rows[5];
    EXPECT_EQ(fastAll.input, kAllInputs);
    EXPECT_EQ(fastAll.variant, "fast");
    EXPECT_NEAR(fastAll.error.meanRelative, 0.175, 1e-15);  // mean of 0.3 and 0.05
    EXPECT_NEAR(fastAll.error.maxRelative, 0.6, 1e-15);     // the largest max
    EXPECT_EQ(fastAll.time.frames, 3);
    EXPECT_TRUE(fastAll.pareto && r.rows[6].pareto);       // 0.175 at 1 ms against 0.1 at 2 ms
}

TEST(ParetoFront, RanksByTheWallClockWhenAskedTo) {
    BenchResults r;
    BenchRow a, b;
    a.input = b.input = "x";
    a.stage = b.stage = "bloom";
    a.variant = "a", b.variant = "b";
    a.time.median = 1.0, a.wall.median = 20.0, a.error.meanRelative = 0.2;  // fast on the timer only
    b.time.median = 2.0, b.wall.median = 10.0, b.error.meanRelative = 0.1;
    r.rows = {a, b};
    markParetoFronts(r);
    EXPECT_TRUE(r.rows[0].pareto && r.rows[1].pareto);
    r.ranked = TimeSource::Wall;
    markParetoFronts(r);
    EXPECT_TRUE(!r.rows[0].pareto && r.rows[1].pareto);
}

TEST(TimeSummary, PercentilesInterpolateBetweenSortedSamples) {
    TimeSummary t = summariseTimes({5, 1, 4, 2, 3, 10, 6, 7, 9, 8, 11});  // 1..11
    EXPECT_EQ(t.frames, 11);
    EXPECT_DOUBLE_EQ(t.median, 6.0);
    EXPECT_DOUBLE_EQ(t.p10, 2.0);
    EXPECT_DOUBLE_EQ(t.p90, 10.0);
    EXPECT_DOUBLE_EQ(t.min, 1.0);
    EXPECT_DOUBLE_EQ(t.max, 11.0);
    TimeSummary two = summariseTimes({1.0, 2.0});
    EXPECT_DOUBLE_EQ(two.median, 1.5);
    EXPECT_DOUBLE_EQ(two.p10, 1.1);
    EXPECT_EQ(summariseTimes({}).frames, 0);
}

}  // namespace
}  // namespace rmfx::accuracy
