#pragma once
// The ratio of two executors' frame times from frames rendered back to back: pair i renders A then
// B when i is even, B then A when odd, so that neither always runs first (after the other's
// work) and a change in the machine's speed falls on both frames of a pair. On a shared machine
// whose speed wanders by tens of percent from second to second, the median of many such ratios,
// with its distribution-free interval (core/MedianInterval.h), says far more than a ratio of two
// medians measured seconds apart.

#include <array>
#include <cstddef>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "core/MedianInterval.h"

namespace rmfx::bench {

// `frame(executor, pair)` renders one frame of executor 0 (A) or 1 (B) for pair `pair` and
// returns N measures of it (its wall-clock milliseconds, its CPU time, …). Returns A / B of each
// pair, for each measure.
template <size_t N>
std::array<std::vector<double>, N> pairedRatiosOf(int pairs, const std::function<std::array<double, N>(int executor, int pair)>& frame) {
    std::array<std::vector<double>, N> ratios;
    for (int i = 0; i < pairs; ++i) {
        std::array<double, N> measures[2];
        const int first = i % 2;
        measures[first] = frame(first, i);
        measures[1 - first] = frame(1 - first, i);
        for (size_t k = 0; k < N; ++k)
            if (measures[1][k] > 0.0) ratios[k].push_back(measures[0][k] / measures[1][k]);
    }
    return ratios;
}

// The same with one measure, the wall-clock milliseconds `frame` returns.
inline std::vector<double> pairedRatios(int pairs, const std::function<double(int executor, int pair)>& frame) {
    return pairedRatiosOf<1>(pairs, [&](int executor, int pair) { return std::array<double, 1>{frame(executor, pair)}; })[0];
}

// "1.043 (1.031 to 1.055)": the median ratio and its 95 % interval; "-" without pairs.
inline std::string medianWithInterval(const std::vector<double>& ratios) {
    if (ratios.empty()) return "-";
    const MedianInterval m = medianInterval(ratios);
    char text[96];
    std::snprintf(text, sizeof text, "%.3f (%.3f to %.3f)", m.median, m.low, m.high);
    return text;
}

}  // namespace rmfx::bench
