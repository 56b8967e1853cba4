#pragma once
// What the benchmarks that compare executors in interleaved rounds (rmfx_bench_content_skip,
// rmfx_bench_health_check) print of their samples, and the CPU time they measure issuing with.

#include <algorithm>
#include <cstdio>
#include <ctime>
#include <string>
#include <vector>

#include "core/Percentile.h"

namespace rmfx::bench {

// The median (core/Percentile.h); 0 without samples.
inline double median(std::vector<double> samples) { return samples.empty() ? 0.0 : percentile(std::move(samples), 0.5); }

// "1.043 (0.950 to 1.210)": the median of per-round ratios and their range; at least one.
inline std::string medianAndRange(const std::vector<double>& ratios) {
    char text[64];
    std::snprintf(text, sizeof text, "%.3f (%.3f to %.3f)", median(ratios), *std::min_element(ratios.begin(), ratios.end()),
                  *std::max_element(ratios.begin(), ratios.end()));
    return text;
}

// This thread's CPU time: what issuing a frame costs the caller, the driver's work on it included.
inline double threadCpuMilliseconds() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) * 1e3 + static_cast<double>(t.tv_nsec) * 1e-6;
}

// The whole process's CPU time, every thread's. On a software rasteriser (llvmpipe) its threads are
// the GPU, so a frame's share of this is the work the frame took, whatever else the machine ran
// meanwhile; on a GPU it is the driver's and rmfx's side only.
inline double processCpuMilliseconds() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) * 1e3 + static_cast<double>(t.tv_nsec) * 1e-6;
}

}  // namespace rmfx::bench
